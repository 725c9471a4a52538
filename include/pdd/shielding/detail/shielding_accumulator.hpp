/// \file shielding_accumulator.hpp
/// Implementation of pdd::compute_shielding_statistics: a per-triangle accumulator and its
/// parallel reduction (every quantity is a count, a minimum or a maximum, so the result does
/// not depend on how the range is split: the same bits for any thread count).
#pragma once

#include <pdd/core/triangle_measures.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/parallel/deterministic_reduce.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <utility>

namespace pdd::detail {

/// The apexes of the input angles < 60 deg, keyed by their coordinates, with those angles.
using small_angle_apex_map = std::map<std::pair<double, double>, double>;

/// The shielding statistics of a range of triangles; join combines two ranges. The smallest
/// angle and the largest radius-edge ratio (1 / (2 sin of the smallest angle)) of either kind
/// of triangle are tracked by the squared sine and measured once (extreme_triangle).
struct shielding_accumulator {
  std::size_t shielded = 0;
  extreme_triangle unshielded_worst; ///< key: the squared sine of the smallest angle
  extreme_triangle shielded_worst;   ///< the same among the shielded triangles
  double max_angle_error = 0.0;

  /// Adds the triangle (p[0], p[1], p[2]); `apex` as small_angle_apexes gives it. The triangle
  /// is shielded when one of its vertices is an apex (the first such corner is its apex).
  void add_triangle(const std::array<point, 3>& p, const small_angle_apex_map& apex) {
    const double sine2 = squared_sine_min_angle(p[0], p[1], p[2]);
    for (std::size_t i = 0; i < 3 && !apex.empty(); ++i)
      if (const auto at = apex.find({p[i].x, p[i].y}); at != apex.end()) {
        ++shielded;
        shielded_worst.offer(sine2, p[0], p[1], p[2]);
        const double angle = angle_at_deg(p[i], p[(i + 1) % 3], p[(i + 2) % 3]);
        max_angle_error = std::max(max_angle_error, std::abs(angle - at->second));
        return;
      }
    unshielded_worst.offer(sine2, p[0], p[1], p[2]);
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
