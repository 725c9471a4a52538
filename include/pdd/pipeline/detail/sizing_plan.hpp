/// \file sizing_plan.hpp
/// The pipeline's planning: the expected triangle count (Algorithm 7.2, bounded by the local
/// feature size) and, with a sizing field, the field's lower bound m(D_i) over every subdomain (for
/// the graded path, Theorem 22).
#pragma once

#include <pdd/concepts/executor.hpp>
#include <pdd/core/bbox.hpp>
#include <pdd/core/decomposition.hpp>
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/geometry/domain_faces.hpp>
#include <pdd/madd/subdomain_region.hpp>
#include <pdd/pipeline/planning.hpp>
#include <pdd/sizing/any_sizing.hpp>
#include <pdd/sizing/domain_region.hpp>
#include <pdd/sizing/inverse_area_integral.hpp>
#include <pdd/sizing/mesh_size_estimate.hpp>
#include <pdd/sizing/sizing_range.hpp>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace pdd::detail {

/// The plan's triangle estimate (Algorithm 7.2, bounded by the local feature size): pdd::
/// estimate_mesh_size under criteria.max_area and the sizing field (2^16 samples of the field;
/// one piece per input triangle for a uniform bound), shields built for `shield_area`.
/// Complexity: that of pdd::estimate_mesh_size.
inline mesh_size_estimate estimate_plan(const pslg& domain, const mesh_criteria& criteria,
                                        const any_sizing& sizing, double shield_area) {
  return estimate_mesh_size(domain, criteria.max_area, sizing, sizing ? std::size_t{1} << 16 : 1,
                            shield_area);
}

/// The plan's triangle estimate for a domain that is not one of closed loops (domain_rule::
/// triangle; pdd::estimate_mesh_size's feature terms need loops): the integral of
/// 1 / (0.656 min(max_area, F)) over its faces (pdd::inverse_area_integral), at least the
/// triangles of its constrained Delaunay triangulation. Small features are not counted, so the
/// estimate is low where the kernel grades down to them. Complexity O(n log n + samples).
inline mesh_size_estimate estimate_faces(const pslg& domain, const domain_faces& faces,
                                         const mesh_criteria& criteria, const any_sizing& sizing) {
  mesh_size_estimate e;
  const std::vector<domain_triangle> triangles = faces.triangles();
  e.area_triangles = inverse_area_integral(domain.vertices, triangles, criteria.max_area, sizing,
                                           sizing ? std::size_t{1} << 16 : 1) /
                     mean_triangle_area_fraction;
  e.triangles = std::max(e.area_triangles, static_cast<double>(triangles.size()));
  return e;
}

/// m(D_i) for every subdomain: pdd::sizing_range's lower bound over the subdomain itself (the
/// field is evaluated only in it), computed on the executor (one job per subdomain). Thread-safe as
/// the field is.
template <Executor E>
std::vector<double> subdomain_sizing_minima(const decomposition& d, const any_sizing& sizing,
                                            const E& executor) {
  const std::size_t m = d.subdomains.size();
  std::vector<double> lo(m), work(m, 1.0);
  executor.run(work,
               [&](index_t s) { lo[s] = sizing_range(sizing, subdomain_region(d, s).view()).lo; });
  return lo;
}

} // namespace pdd::detail
