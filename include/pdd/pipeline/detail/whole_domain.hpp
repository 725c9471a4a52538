/// \file whole_domain.hpp
/// The pipeline's plan for a domain that is not one of closed loops (Triangle's rule; meshed
/// whole, or decoupled from its faces), and the kernel on the whole domain with its small input
/// angles shielded (pipeline::mesh_whole).
#pragma once

#include <pdd/concepts/delaunay_mesher.hpp>
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/errors.hpp>
#include <pdd/geometry/domain_angles.hpp>
#include <pdd/geometry/properties.hpp>
#include <pdd/madd/madd_start.hpp>
#include <pdd/mesh/verify.hpp>
#include <pdd/pipeline/detail/path_plan.hpp>
#include <pdd/pipeline/options.hpp>
#include <pdd/pipeline/planning.hpp>
#include <pdd/shielding/apply_shields.hpp>
#include <pdd/shielding/shield.hpp>
#include <pdd/sizing/any_sizing.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>

namespace pdd::detail {

/// What the plan knows of a domain that is not one of closed loops.
struct general_domain_plan {
  std::size_t regions = 0; ///< faces and caps (each at least one subdomain)
  std::string cap_reason;  ///< the caps and why (pdd::madd_start::cap_reason)
};

/// A domain that is not one of closed loops (read by Triangle's rule): the regions MADD starts
/// from (`start`: null when one subdomain is asked for, they are then not needed).
inline general_domain_plan plan_general_domain(const madd_start* start) {
  general_domain_plan p;
  if (!start) return p;
  p.regions = start->regions().size();
  p.cap_reason = start->cap_reason();
  return p;
}

/// N for a domain that is not one of closed loops, from the N `planned` as for closed loops:
/// 1 when one is planned, else at least one subdomain per region (MADD splits regions, it
/// never merges two: the segment between them would lie inside a subdomain). `reason`
/// receives the plan's reason, which says when N was raised and why there are caps.
inline std::size_t general_domain_subdomains(std::size_t planned, const general_domain_plan& p,
                                             std::string& reason) {
  if (planned <= 1) {
    reason = general_domain_reason;
    return 1;
  }
  reason = "the domain is not one of closed loops: MADD from its " + std::to_string(p.regions) +
           (p.cap_reason.empty() ? " faces, the segments between faces are interfaces"
                                 : " regions (faces and caps), the segments between them are "
                                   "interfaces; " +
                                       p.cap_reason);
  if (planned < p.regions)
    reason += "; N raised from " + std::to_string(planned) + " to " + std::to_string(p.regions) +
              ", one subdomain per face at least";
  return std::max(planned, p.regions);
}

/// The plan's N: o.subdomains when set; else automatic_subdomains of the estimate when some
/// area bound is given, 1 without any (the kernel then grades the mesh by the geometry alone);
/// on a domain not of closed loops (`general`: its plan) as general_domain_subdomains, which
/// writes the plan's `reason`.
inline std::size_t planned_subdomains(const generate_options& o, double estimated_triangles,
                                      unsigned threads, const general_domain_plan* general,
                                      std::string& reason) {
  const bool bounded = o.sizing || std::isfinite(o.criteria.max_area);
  const std::size_t n = o.subdomains != 0 ? o.subdomains
                        : bounded ? automatic_subdomains(estimated_triangles, threads, o.planning)
                                  : 1;
  return general ? general_domain_subdomains(n, *general, reason) : n;
}

/// Whether a domain is meshed whole because of its small input angles: the angle bound is
/// above Ruppert's (pdd::within_ruppert_bound), where neither the shields nor the decoupling
/// path beside small angles hold (Triangle's Texas at 33 deg: CGAL's kernel refined without end
/// beside a shield; the native kernel split it from 31 deg; the Bahamas at 25-30 deg: the path
/// split beyond repair), and some angle of the domain between segments
/// (pdd::domain_angles) is below 60 deg, the shields' and the clusters' threshold. Then
/// `reason` receives why. Complexity O(n log n).
inline bool small_angles_above_ruppert(const pslg& domain, const mesh_criteria& c,
                                       std::string& reason) {
  if (c.within_ruppert_bound()) return false;
  domain_angle smallest;
  for (const domain_angle& a : domain_angles(domain))
    if (a.angle_deg < smallest.angle_deg) smallest = a;
  if (!(smallest.angle_deg < 60.0)) return false;
  reason = "one subdomain: an angle bound of " + number_text(c.min_angle_deg) +
           " deg, above Ruppert's 20.7 deg, and input angles below 60 deg (" +
           number_text(smallest.angle_deg) + " deg at vertex " + std::to_string(smallest.vertex) +
           "): the shields and the decoupling path hold up to 20.7 deg only (Theorem 24), so "
           "the kernel meshes the whole domain with its own rule at the small angles";
  return true;
}

/// The kernel's unshielded mesh of a domain of closed loops above Ruppert's bound, verified
/// (pdd::verify, the domain as given): beyond the bound a kernel's small-angle rule is not
/// proven to keep its split points on their segments (CGAL's kernel at 33 deg on the Bahamas,
/// --max-area 1.6e-4: a split point 1e-14 from an input vertex and off its segment), so a mesh
/// that fails is refused, never delivered: an input beyond what the kernel resolves.
/// \throws pdd::unresolvable_input_error(-1, ...) naming the first failure.
template <DelaunayMesher M>
triangle_mesh mesh_verified_above_ruppert(const M& mesher, const pslg& domain,
                                          const mesh_criteria& criteria, const any_sizing& sizing) {
  triangle_mesh m = mesher.mesh(domain, criteria, sizing).mesh;
  verify_options vo;
  vo.criteria = criteria;
  vo.rule_as_given = true;
  const verification_report rep = sizing ? verify(m, domain, vo, sizing) : verify(m, domain, vo);
  if (rep.ok()) return m;
  throw unresolvable_input_error(
      -1, "above Ruppert's bound (20.7 deg) the kernel's mesh of the small input angles fails "
          "verification (" +
              (rep.messages.empty() ? std::string("see pdd::verify") : rep.messages.front()) +
              "); the native kernel meshes them by Triangle's rules (--kernel native), or bound "
              "the angle at 20.7 deg");
}

/// The kernel on the whole domain, markers 0: a general domain as it is; a domain of closed
/// loops with its input angles < 60 deg shielded first (pdd::shield with `shield_area`,
/// Algorithm 8.2 with N = 1), the kernel on D' and the shielded triangles added as they are
/// (`shielded_triangles` receives their number); above Ruppert's bound
/// (pdd::within_ruppert_bound, where Theorem 24 does not hold) unshielded, the kernel's own
/// rule meshing the small angles as on a general domain (pdd::quality_exemptions exempts
/// what that rule leaves) and the mesh verified (mesh_verified_above_ruppert); a domain with
/// no input angle below 60 deg has no shields and is meshed as it is, unverified.
/// \throws pdd::meshing_error(-1, ...) from the kernel, or when it split a shield edge;
/// pdd::unresolvable_input_error as mesh_verified_above_ruppert; pdd::geometry_error as
/// pdd::shield.
template <DelaunayMesher M>
triangle_mesh mesh_whole_domain(const M& mesher, const pslg& domain, bool general,
                                const mesh_criteria& criteria, const any_sizing& sizing,
                                double shield_area, std::size_t& shielded_triangles) {
  shielded_triangles = 0;
  if (general) return mesher.mesh(domain, criteria, sizing).mesh;
  if (!criteria.within_ruppert_bound() && min_domain_angle_deg(domain) < 60.0)
    return mesh_verified_above_ruppert(mesher, domain, criteria, sizing);
  const shielded_domain sd = shield(domain, shield_area);
  shielded_triangles = sd.triangles.size();
  if (sd.triangles.empty()) return mesher.mesh(domain, criteria, sizing).mesh;
  mesher_result r = mesher.mesh(sd.domain, criteria, sizing);
  const std::size_t splits = add_shield_triangles(r, sd.domain, sd.triangles, 0);
  if (splits != 0)
    throw meshing_error(-1, std::to_string(splits) +
                                " shield edge(s) were split by the kernel (Theorem 24 (5) "
                                "excludes it for a Ruppert-type kernel)");
  return std::move(r.mesh);
}

} // namespace pdd::detail
