/// \file shield_statistics.hpp
/// Quality accounting of meshes with shielded small angles (dissertation 8.1, Theorem 24):
/// which triangles are shielded, and their statistics apart from the others.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_measures.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/geometry/domain_angles.hpp>
#include <pdd/geometry/loops.hpp>
#include <pdd/geometry/properties.hpp>
#include <pdd/geometry/validate.hpp>
#include <pdd/shielding/detail/plan.hpp>
#include <pdd/shielding/detail/shielding_accumulator.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace pdd {

namespace detail {
/// The apexes of the domain's angles < 60 deg (domain side) with their one sector each
/// (closed loops: every vertex is on two segments).
inline small_angle_apex_map small_angle_apexes(const pslg& domain) {
  small_angle_apex_map apex;
  const loop_structure ls = find_loops(domain);
  for (const polygon_loop& l : ls.loops) {
    const std::size_t n = l.vertices.size();
    for (std::size_t i = 0; i < n; ++i) {
      const point& prev = domain.vertices[l.vertices[(i + n - 1) % n]];
      const point& v = domain.vertices[l.vertices[i]];
      const point& next = domain.vertices[l.vertices[(i + 1) % n]];
      const point from = l.domain_on_left() ? next : prev, to = l.domain_on_left() ? prev : next;
      const double a = ccw_angle_deg(v, from, to);
      if (a < shield_threshold_deg) apex[{v.x, v.y}] = {{from, to, a}};
    }
  }
  return apex;
}
} // namespace detail

/// The small input angles of a domain: the apexes of its angles < 60 deg (domain side), keyed
/// by their coordinates, with those angles, and its smallest input angle. What
/// find_shielded_triangles and compute_shielding_statistics look up per triangle, found once
/// for many meshes of one domain (every subdomain mesh of a run: finding the loops of a domain
/// of 1,152 vertices for each of 267 subdomains cost more than meshing them).
struct small_input_angles {
  /// The vertices with a domain-side angle < 60 deg, keyed by their coordinates (x, y), each
  /// with its sectors there (one on closed loops, several at a pinch vertex or where
  /// constraints meet); empty when the domain has no small angle.
  detail::small_angle_apex_map apexes;
  double min_input_angle_deg = 360.0; ///< pdd::min_domain_angle_deg
};

/// The small input angles of `domain`. On a domain of domain_rule::triangle that is not one of
/// closed loops, the angles between consecutive segments at a vertex on the domain side
/// (internal and dangling constraints included, detail::for_each_domain_angle): the kernel
/// meshes such a domain unshielded, and CGAL's clusters (concentric shells, see
/// kernels/cgal/detail/cluster_rule.hpp) leave the triangles at these apexes below the bound.
/// \pre domain valid. \throws geometry_error as find_loops() (odd_nesting) or validate().
/// Complexity O(n log n). Thread-safe.
inline small_input_angles find_small_input_angles(const pslg& domain) {
  if (domain.rule == domain_rule::triangle && !has_closed_loops(domain)) {
    small_input_angles out;
    const std::vector<domain_angle> angles = domain_angles(domain); // by vertex
    for (std::size_t i = 0, j = 0; i < angles.size(); i = j) {
      bool small = false;
      for (j = i; j < angles.size() && angles[j].vertex == angles[i].vertex; ++j) {
        out.min_input_angle_deg = std::min(out.min_input_angle_deg, angles[j].angle_deg);
        small = small || angles[j].angle_deg < detail::shield_threshold_deg;
      }
      if (!small) continue;
      const point& v = domain.vertices[angles[i].vertex];
      auto& sectors = out.apexes[{v.x, v.y}];
      for (std::size_t k = i; k < j; ++k)
        sectors.push_back(
            {domain.vertices[angles[k].from], domain.vertices[angles[k].to], angles[k].angle_deg});
    }
    return out;
  }
  return {detail::small_angle_apexes(domain), min_domain_angle_deg(domain)};
}

/// Per triangle of m: 1 when it is a shielded triangle, i.e. it has a corner in a sector
/// < 60 deg of the domain at an apex (a shielded apex lies in exactly its shielded triangle;
/// vertices are matched by coordinates; at a pinch vertex only the triangles in its small
/// sectors count). Use it as verify_options::quality_exempt.
/// Complexity O(T log s). Thread-safe.
inline std::vector<char> find_shielded_triangles(const triangle_mesh& m,
                                                 const small_input_angles& angles) {
  const auto& apex = angles.apexes;
  std::vector<char> flag(m.triangles.size(), 0);
  if (apex.empty()) return flag;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto& tri = m.triangles[t];
    const std::array<point, 3> p{m.vertices[tri[0]], m.vertices[tri[1]], m.vertices[tri[2]]};
    for (std::size_t i = 0; i < 3; ++i)
      if (detail::shielding_accumulator::small_sector_angle(p, i, apex) <
          detail::shield_threshold_deg)
        flag[t] = 1;
  }
  return flag;
}

/// find_shielded_triangles of the small input angles of `domain`.
/// \pre domain valid (closed loops). 	hrows geometry_error as find_loops().
/// Complexity O(n log n + T log s). Thread-safe.
inline std::vector<char> find_shielded_triangles(const triangle_mesh& m, const pslg& domain) {
  return find_shielded_triangles(m, find_small_input_angles(domain));
}

/// Statistics of the shielded triangles apart from the others (Theorem 24 (1), (7)).
struct shielding_statistics {
  /// The number of shielded triangles in the mesh (0 when the domain has no small angle).
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

/// Computes shielding_statistics of a mesh with the small input angles `angles`
/// (find_small_input_angles; shielded triangles as find_shielded_triangles finds them).
/// Complexity O(T log s), in parallel (oneTBB). Thread-safe; the same result for any thread
/// count (counts, minima and maxima only).
inline shielding_statistics compute_shielding_statistics(const triangle_mesh& m,
                                                         const small_input_angles& angles) {
  shielding_statistics st;
  st.min_input_angle_deg = angles.min_input_angle_deg;
  const detail::shielding_accumulator acc = detail::accumulate_shielding(m, angles.apexes);
  st.shielded_triangles = acc.shielded;
  const double min_unshielded = acc.min_angle_unshielded();
  st.min_angle_unshielded_deg = std::isfinite(min_unshielded) ? min_unshielded : 0.0;
  st.max_ratio_unshielded = detail::shielding_accumulator::max_ratio(acc.unshielded_worst);
  st.max_ratio_shielded = detail::shielding_accumulator::max_ratio(acc.shielded_worst);
  st.max_shield_angle_error_deg = acc.max_angle_error;
  return st;
}

/// compute_shielding_statistics of a mesh of `domain`. 	hrows geometry_error as
/// find_loops().
inline shielding_statistics compute_shielding_statistics(const triangle_mesh& m,
                                                         const pslg& domain) {
  return compute_shielding_statistics(m, find_small_input_angles(domain));
}

} // namespace pdd
