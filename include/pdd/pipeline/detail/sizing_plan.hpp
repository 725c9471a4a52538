/// \file sizing_plan.hpp
/// The pipeline's planning with a sizing field: the expected triangle count (Algorithm 7.2)
/// and the field's lower bound m(D_i) over every subdomain (for the graded path, Theorem 22).
#pragma once

#include <pdd/concepts/executor.hpp>
#include <pdd/core/bbox.hpp>
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/madd/decomposition.hpp>
#include <pdd/pipeline/planning.hpp>
#include <pdd/sizing/any_sizing.hpp>
#include <pdd/sizing/inverse_area_integral.hpp>
#include <pdd/sizing/sizing_range.hpp>

#include <algorithm>
#include <limits>
#include <vector>

namespace pdd::detail {

/// Expected triangles of a mesh graded by `sizing` (and criteria.max_area): the integral of
/// 1 / (0.656 F) over the domain (Algorithm 7.2); infinity when that is not positive (no
/// finite bound anywhere). Complexity: that of pdd::inverse_area_integral.
inline double estimate_graded_triangles(const pslg& domain, const mesh_criteria& criteria,
                                        const any_sizing& sizing) {
  const double e =
      inverse_area_integral(domain, criteria.max_area, sizing) / mean_triangle_area_fraction;
  return e > 0.0 ? e : std::numeric_limits<double>::infinity();
}

/// m(D_i) for every subdomain: pdd::sizing_range's lower bound over the subdomain's bounding
/// box, computed on the executor (one job per subdomain). Thread-safe as the field is.
template <Executor E>
std::vector<double> subdomain_sizing_minima(const decomposition& d, const any_sizing& sizing,
                                            const E& executor) {
  const std::size_t m = d.subdomains.size();
  std::vector<double> lo(m), work(m, 1.0);
  executor.run(work, [&](index_t s) {
    pdd::bbox b;
    for (const auto& loop : d.subdomains[s].loops)
      for (const index_t v : loop) {
        const point& p = d.vertices[v];
        b = {std::min(b.xmin, p.x), std::min(b.ymin, p.y), std::max(b.xmax, p.x),
             std::max(b.ymax, p.y)};
      }
    lo[s] = sizing_range(sizing, b).lo;
  });
  return lo;
}

} // namespace pdd::detail
