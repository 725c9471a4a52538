/// \file shield_statistics.hpp
/// Quality accounting of meshes with shielded small angles (dissertation 8.1, Theorem 24):
/// which triangles are shielded, and their statistics apart from the others.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_measures.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/geometry/loops.hpp>
#include <pdd/geometry/properties.hpp>
#include <pdd/shielding/detail/plan.hpp>
#include <pdd/shielding/detail/shielding_accumulator.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace pdd {

namespace detail {
/// The apexes of the domain's angles < 60 deg (domain side) with their angles in degrees.
inline small_angle_apex_map small_angle_apexes(const pslg& domain) {
  small_angle_apex_map apex;
  const loop_structure ls = find_loops(domain);
  for (const polygon_loop& l : ls.loops) {
    const std::size_t n = l.vertices.size();
    for (std::size_t i = 0; i < n; ++i) {
      const point& prev = domain.vertices[l.vertices[(i + n - 1) % n]];
      const point& v = domain.vertices[l.vertices[i]];
      const point& next = domain.vertices[l.vertices[(i + 1) % n]];
      const double a =
          l.domain_on_left() ? ccw_angle_deg(v, next, prev) : ccw_angle_deg(v, prev, next);
      if (a < shield_threshold_deg) apex[{v.x, v.y}] = a;
    }
  }
  return apex;
}
} // namespace detail

/// Per triangle of m: 1 when it is a shielded triangle of `domain`, i.e. it has a vertex at
/// the apex of an input angle < 60 deg (a shielded apex lies in exactly its shielded triangle;
/// vertices are matched by coordinates). Use it as verify_options::quality_exempt.
/// \pre domain valid (closed loops). \throws geometry_error as find_loops().
/// Complexity O(n log n + T log s). Thread-safe.
inline std::vector<char> find_shielded_triangles(const triangle_mesh& m, const pslg& domain) {
  const auto apex = detail::small_angle_apexes(domain);
  std::vector<char> flag(m.triangles.size(), 0);
  if (apex.empty()) return flag;
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (const index_t v : m.triangles[t])
      if (apex.count({m.vertices[v].x, m.vertices[v].y})) flag[t] = 1;
  return flag;
}

/// Statistics of the shielded triangles apart from the others (Theorem 24 (1), (7)).
struct shielding_statistics {
  std::size_t shielded_triangles = 0;
  /// Smallest angle of the triangles that are not shielded (0 for none).
  double min_angle_unshielded_deg = 0.0;
  /// Largest circumradius-to-shortest-edge ratio of the triangles that are not shielded.
  double max_ratio_unshielded = 0.0;
  /// Smallest input angle on the domain side (pdd::min_domain_angle_deg).
  double min_input_angle_deg = 360.0;
  /// Largest ratio of a shielded triangle (Theorem 24 (7): 1 / (2 sin theta)).
  double max_ratio_shielded = 0.0;
  /// Largest |angle of a shielded triangle at its apex - the input angle there| (degrees).
  double max_shield_angle_error_deg = 0.0;
};

/// Computes shielding_statistics of a mesh of `domain` (shielded triangles as
/// find_shielded_triangles finds them). \throws geometry_error as find_loops().
/// Complexity O(T log s), in parallel (oneTBB). Thread-safe; the same result for any thread
/// count (counts, minima and maxima only).
inline shielding_statistics compute_shielding_statistics(const triangle_mesh& m,
                                                         const pslg& domain) {
  const auto apex = detail::small_angle_apexes(domain);
  shielding_statistics st;
  st.min_input_angle_deg = min_domain_angle_deg(domain);
  const detail::shielding_accumulator acc = detail::accumulate_shielding(m, apex);
  st.shielded_triangles = acc.shielded;
  st.min_angle_unshielded_deg =
      std::isfinite(acc.min_angle_unshielded) ? acc.min_angle_unshielded : 0.0;
  st.max_ratio_unshielded = acc.max_ratio_unshielded;
  st.max_ratio_shielded = acc.max_ratio_shielded;
  st.max_shield_angle_error_deg = acc.max_angle_error;
  return st;
}

} // namespace pdd
