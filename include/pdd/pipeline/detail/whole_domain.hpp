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
#include <pdd/madd/madd_start.hpp>
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

/// The kernel on the whole domain, markers 0: a general domain as it is; a domain of closed
/// loops with its input angles < 60 deg shielded first (pdd::shield with `shield_area`,
/// Algorithm 8.2 with N = 1), the kernel on D' and the shielded triangles added as they are
/// (`shielded_triangles` receives their number).
/// \throws pdd::meshing_error(-1, ...) from the kernel, or when it split a shield edge;
/// pdd::geometry_error as pdd::shield.
template <DelaunayMesher M>
triangle_mesh mesh_whole_domain(const M& mesher, const pslg& domain, bool general,
                                const mesh_criteria& criteria, const any_sizing& sizing,
                                double shield_area, std::size_t& shielded_triangles) {
  shielded_triangles = 0;
  if (general) return mesher.mesh(domain, criteria, sizing).mesh;
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
