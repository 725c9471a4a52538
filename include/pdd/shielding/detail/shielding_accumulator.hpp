/// \file shielding_accumulator.hpp
/// Implementation of pdd::compute_shielding_statistics: a per-triangle accumulator and its
/// parallel reduction (every quantity is a count, a minimum or a maximum, so the result does
/// not depend on how the range is split: the same bits for any thread count).
#pragma once

#include <pdd/core/thread_sanitizer.hpp>
#include <pdd/core/triangle_measures.hpp>
#include <pdd/core/triangle_mesh.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

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

/// The shielding statistics of a range of triangles; join combines two ranges.
struct shielding_accumulator {
  std::size_t shielded = 0;
  double min_angle_unshielded = std::numeric_limits<double>::infinity();
  double max_ratio_unshielded = 0.0;
  double max_ratio_shielded = 0.0;
  double max_angle_error = 0.0;

  /// Adds the triangle (p[0], p[1], p[2]); `apex` as small_angle_apexes gives it. The triangle
  /// is shielded when one of its vertices is an apex (the first such corner is its apex).
  void add_triangle(const std::array<point, 3>& p, const small_angle_apex_map& apex) {
    const double ratio = radius_edge_ratio(p[0], p[1], p[2]);
    for (std::size_t i = 0; i < 3 && !apex.empty(); ++i)
      if (const auto at = apex.find({p[i].x, p[i].y}); at != apex.end()) {
        ++shielded;
        max_ratio_shielded = std::max(max_ratio_shielded, ratio);
        const double angle = angle_at_deg(p[i], p[(i + 1) % 3], p[(i + 2) % 3]);
        max_angle_error = std::max(max_angle_error, std::abs(angle - at->second));
        return;
      }
    min_angle_unshielded = std::min(min_angle_unshielded, smallest_angle_deg(p[0], p[1], p[2]));
    max_ratio_unshielded = std::max(max_ratio_unshielded, ratio);
  }

  void join(const shielding_accumulator& o) {
    shielded += o.shielded;
    min_angle_unshielded = std::min(min_angle_unshielded, o.min_angle_unshielded);
    max_ratio_unshielded = std::max(max_ratio_unshielded, o.max_ratio_unshielded);
    max_ratio_shielded = std::max(max_ratio_shielded, o.max_ratio_shielded);
    max_angle_error = std::max(max_angle_error, o.max_angle_error);
  }
};

/// The accumulated shielding statistics of all triangles of m, in parallel.
inline shielding_accumulator accumulate_shielding(const triangle_mesh& m,
                                                  const small_angle_apex_map& apex) {
  using range = tbb::blocked_range<std::size_t>;
  const tsan_fork_join fork_join;
  const auto body = [&](const range& r, shielding_accumulator acc) {
    tsan_fork_join::task_begins();
    const auto task = fork_join.task();
    for (std::size_t t = r.begin(); t != r.end(); ++t) {
      const auto& tri = m.triangles[t];
      acc.add_triangle({m.vertices[tri[0]], m.vertices[tri[1]], m.vertices[tri[2]]}, apex);
    }
    return acc;
  };
  const shielding_accumulator acc = tbb::parallel_deterministic_reduce(
      range(0, m.triangles.size(), 4096), shielding_accumulator{}, body,
      [&](shielding_accumulator x, const shielding_accumulator& y) {
        tsan_fork_join::task_begins();
        const auto task = fork_join.task();
        x.join(y);
        return x;
      });
  fork_join.join();
  return acc;
}

} // namespace pdd::detail
