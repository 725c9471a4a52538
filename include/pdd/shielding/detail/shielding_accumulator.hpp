/// \file shielding_accumulator.hpp
/// Implementation of pdd::compute_shielding_statistics: a per-triangle accumulator and its
/// parallel reduction (every quantity is a count, a minimum or a maximum, so the result does
/// not depend on how the range is split: the same bits for any thread count).
#pragma once

#include <pdd/core/kernel.hpp>
#include <pdd/core/ray_order.hpp>
#include <pdd/core/triangle_measures.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/parallel/deterministic_reduce.hpp>
#include <pdd/shielding/detail/plan.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace pdd::detail {

/// One sector of the domain at a vertex: counter-clockwise from the ray to `from` to the ray
/// to `to` (the same ray: all around the vertex), and its angle in degrees.
struct apex_sector {
  point from, to;
  double angle_deg = 360.0;
};

/// The vertices with an input angle < 60 deg, keyed by their coordinates, with the sectors of
/// the domain there: one on closed loops; several at a pinch vertex or where constraints meet.
using small_angle_apex_map = std::map<std::pair<double, double>, std::vector<apex_sector>>;

/// The sector of `sectors` (at `apex`) that holds the triangle (apex, b, c), null when none
/// does: the one whose counter-clockwise sweep from its `from` ray reaches the ray to the
/// triangle's centroid before its `to` ray (exact predicates on the centroid, which lies
/// inside the triangle's corner even where a split or shield point on a sector's segment is
/// rounded off its ray).
inline const apex_sector* sector_of_triangle(const std::vector<apex_sector>& sectors, point apex,
                                             point b, point c) {
  if (sectors.size() == 1) return &sectors.front();
  const point centroid{(apex.x + b.x + c.x) / 3.0, (apex.y + b.y + c.y) / 3.0};
  for (const apex_sector& s : sectors)
    if (ray_turn_class(apex, s.from, s.to) == 0 || ray_turns_before(apex, s.from, centroid, s.to))
      return &s;
  return nullptr;
}

/// The shielding statistics of a range of triangles; join combines two ranges. The smallest
/// angle and the largest radius-edge ratio (1 / (2 sin of the smallest angle)) of either kind
/// of triangle are tracked by the squared sine and measured once (extreme_triangle).
struct shielding_accumulator {
  std::size_t shielded = 0;
  extreme_triangle unshielded_worst; ///< key: the squared sine of the smallest angle
  extreme_triangle shielded_worst;   ///< the same among the shielded triangles
  double max_angle_error = 0.0;

  /// Adds the triangle (p[0], p[1], p[2]); `apex` as small_angle_apexes gives it. The triangle
  /// is shielded when one of its corners lies in a sector < 60 deg at an apex (the first such
  /// corner is its apex).
  void add_triangle(const std::array<point, 3>& p, const small_angle_apex_map& apex) {
    const double sine2 = squared_sine_min_angle(p[0], p[1], p[2]);
    for (std::size_t i = 0; i < 3 && !apex.empty(); ++i)
      if (const double input = small_sector_angle(p, i, apex); input < shield_threshold_deg) {
        ++shielded;
        shielded_worst.offer(sine2, p[0], p[1], p[2]);
        const double angle = angle_at_deg(p[i], p[(i + 1) % 3], p[(i + 2) % 3]);
        max_angle_error = std::max(max_angle_error, std::abs(angle - input));
        return;
      }
    unshielded_worst.offer(sine2, p[0], p[1], p[2]);
  }

  /// The angle of the sector that holds corner i of triangle p when p[i] is an apex, else 360.
  static double small_sector_angle(const std::array<point, 3>& p, std::size_t i,
                                   const small_angle_apex_map& apex) {
    const auto at = apex.find({p[i].x, p[i].y});
    if (at == apex.end()) return 360.0;
    const apex_sector* s = sector_of_triangle(at->second, p[i], p[(i + 1) % 3], p[(i + 2) % 3]);
    return s ? s->angle_deg : 360.0;
  }

  void join(const shielding_accumulator& o) {
    shielded += o.shielded;
    unshielded_worst.join(o.unshielded_worst);
    shielded_worst.join(o.shielded_worst);
    max_angle_error = std::max(max_angle_error, o.max_angle_error);
  }

  /// The smallest angle of the unshielded triangles (infinity: none).
  double min_angle_unshielded() const {
    const auto& p = unshielded_worst.corners;
    return unshielded_worst.found ? smallest_angle_deg(p[0], p[1], p[2])
                                  : std::numeric_limits<double>::infinity();
  }
  static double max_ratio(const extreme_triangle& worst) {
    const auto& p = worst.corners;
    return worst.found ? radius_edge_ratio(p[0], p[1], p[2]) : 0.0;
  }
};

/// The accumulated shielding statistics of all triangles of m, in parallel (deterministic).
inline shielding_accumulator accumulate_shielding(const triangle_mesh& m,
                                                  const small_angle_apex_map& apex) {
  return deterministic_reduce(
      m.triangles.size(), shielding_accumulator{},
      [&](shielding_accumulator& acc, std::size_t begin, std::size_t end) {
        for (std::size_t t = begin; t != end; ++t) {
          const auto& tri = m.triangles[t];
          acc.add_triangle({m.vertices[tri[0]], m.vertices[tri[1]], m.vertices[tri[2]]}, apex);
        }
      },
      [](shielding_accumulator& into, const shielding_accumulator& from) { into.join(from); });
}

} // namespace pdd::detail
