/// \file decomposition_measures.hpp
/// pdd::measure_decomposition: the quality measures of a decomposition (dissertation 5.2:
/// separator angles, lengths and subdomain areas).
#pragma once

#include <pdd/core/decomposition.hpp>
#include <pdd/madd/decomposition_statistics.hpp>
#include <pdd/madd/detail/region.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace pdd {

/// Fills the geometric fields of st (subdomains, min_separator_angle_deg, separator lengths,
/// area ratios, min_interface_edge_rel) from d; the counters and time_s are left as they are.
/// The separator angles are the interior angles of the subdomains at every vertex with an
/// incident interface edge (each angle a separator forms with the boundary or with another
/// separator is one of them). Complexity O(size of d). Thread-safe.
inline void measure_decomposition(const decomposition& d, decomposition_statistics& st) {
  const std::size_t n = d.subdomains.size();
  st.subdomains = n;
  st.min_separator_angle_deg = 180.0;
  st.separator_length_total = 0.0;
  st.separator_length_per_subdomain.assign(n, 0.0);
  double total = 0.0, amax = 0.0, amin = std::numeric_limits<double>::infinity();
  double emin = std::numeric_limits<double>::infinity();
  for (std::size_t s = 0; s < n; ++s) {
    const subdomain& sd = d.subdomains[s];
    total += sd.area;
    amax = std::max(amax, sd.area);
    amin = std::min(amin, sd.area);
    for (std::size_t l = 0; l < sd.loops.size(); ++l) {
      const auto& loop = sd.loops[l];
      const auto& tags = sd.tags[l];
      const std::size_t m = loop.size();
      for (std::size_t i = 0; i < m; ++i) {
        const bool out_if = tags[i].type == edge_tag::kind::interface;
        const bool in_if = tags[(i + m - 1) % m].type == edge_tag::kind::interface;
        const point v = d.vertices[loop[i]];
        if (out_if) {
          const double len = detail::distance(v, d.vertices[loop[(i + 1) % m]]);
          st.separator_length_per_subdomain[s] += len;
          st.separator_length_total += 0.5 * len;
          emin = std::min(emin, len);
        }
        if (out_if || in_if)
          st.min_separator_angle_deg =
              std::min(st.min_separator_angle_deg,
                       detail::interior_angle_deg(d.vertices[loop[(i + m - 1) % m]], v,
                                                  d.vertices[loop[(i + 1) % m]]));
      }
    }
  }
  const double mean = n > 0 ? total / static_cast<double>(n) : 0.0;
  st.max_area_over_mean = mean > 0.0 ? amax / mean : 0.0;
  st.min_area_over_mean = mean > 0.0 ? amin / mean : 0.0;
  st.min_interface_edge_rel = std::isfinite(emin) && mean > 0.0 ? emin / std::sqrt(mean) : 0.0;
}

} // namespace pdd
