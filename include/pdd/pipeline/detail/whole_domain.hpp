/// \file whole_domain.hpp
/// The pipeline's one-subdomain path: a domain that is not one of closed loops (Triangle's
/// rule, meshed whole), and the kernel on the whole domain with its small input angles
/// shielded (pipeline::mesh_whole).
#pragma once

#include <pdd/concepts/delaunay_mesher.hpp>
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/errors.hpp>
#include <pdd/pipeline/detail/path_plan.hpp>
#include <pdd/pipeline/options.hpp>
#include <pdd/shielding/apply_shields.hpp>
#include <pdd/shielding/shield.hpp>
#include <pdd/sizing/any_sizing.hpp>

#include <cstddef>
#include <string>
#include <utility>

namespace pdd::detail {

/// A domain that is not one of closed loops: Triangle's rule for the kernel, one subdomain.
/// \throws pdd::decomposition_error for options.subdomains > 1.
inline void plan_general_domain(pslg& domain, generate_options& options) {
  domain.rule = domain_rule::triangle;
  if (options.subdomains > 1) throw decomposition_error(general_domain_error(options.subdomains));
  options.subdomains = 1;
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
