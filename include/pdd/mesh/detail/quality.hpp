/// \file quality.hpp
/// Implementation of pdd::compute_statistics: a per-triangle accumulator and its
/// deterministic parallel reduction.
#pragma once

#include <pdd/core/thread_sanitizer.hpp>
#include <pdd/core/triangle_measures.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/mesh/mesh_statistics.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace pdd::detail {

/// The statistics of a range of triangles; join combines two ranges.
struct statistics_accumulator {
  double min_angle = std::numeric_limits<double>::infinity();
  double max_angle = 0.0;
  double max_ratio = 0.0;
  double max_area = 0.0;
  double max_area_ratio = 0.0;
  double area = 0.0;
  std::array<std::size_t, 180> histogram{};

  /// Adds the triangle (a, b, c) whose area bound at the centroid is `bound` (inf: none).
  void add_triangle(const point& a, const point& b, const point& c, double bound) {
    for (const double angle : triangle_angles_deg(a, b, c)) {
      min_angle = std::min(min_angle, angle);
      max_angle = std::max(max_angle, angle);
      const auto bin = static_cast<std::size_t>(std::clamp(std::floor(angle), 0.0, 179.0));
      ++histogram[bin];
    }
    max_ratio = std::max(max_ratio, radius_edge_ratio(a, b, c));
    const double tri_area = triangle_area(a, b, c);
    max_area = std::max(max_area, tri_area);
    area += tri_area;
    if (!std::isinf(bound)) max_area_ratio = std::max(max_area_ratio, tri_area / bound);
  }

  void join(const statistics_accumulator& o) {
    min_angle = std::min(min_angle, o.min_angle);
    max_angle = std::max(max_angle, o.max_angle);
    max_ratio = std::max(max_ratio, o.max_ratio);
    max_area = std::max(max_area, o.max_area);
    max_area_ratio = std::max(max_area_ratio, o.max_area_ratio);
    area += o.area;
    for (std::size_t k = 0; k < histogram.size(); ++k)
      histogram[k] += o.histogram[k];
  }
};

/// Fixed grain of the deterministic reduction (the tree shape depends on it only).
inline constexpr std::size_t statistics_grain = 4096;

/// The accumulated statistics of all triangles of m, in parallel.
/// parallel_deterministic_reduce splits and joins the same way for any thread count, so the
/// floating-point sum of areas is bitwise reproducible.
template <class AreaBound>
statistics_accumulator accumulate_statistics(const triangle_mesh& m, const AreaBound& bound_at) {
  using range = tbb::blocked_range<std::size_t>;
  const tsan_fork_join fork_join;
  const auto body = [&](const range& r, statistics_accumulator acc) {
    tsan_fork_join::task_begins();
    const auto task = fork_join.task();
    for (std::size_t t = r.begin(); t != r.end(); ++t) {
      const auto& tri = m.triangles[t];
      const point& a = m.vertices[tri[0]];
      const point& b = m.vertices[tri[1]];
      const point& c = m.vertices[tri[2]];
      acc.add_triangle(a, b, c, bound_at(triangle_centroid(a, b, c)));
    }
    return acc;
  };
  const statistics_accumulator acc = tbb::parallel_deterministic_reduce(
      range(0, m.triangles.size(), statistics_grain), statistics_accumulator{}, body,
      [&](statistics_accumulator x, const statistics_accumulator& y) {
        tsan_fork_join::task_begins();
        const auto task = fork_join.task();
        x.join(y);
        return x;
      });
  fork_join.join();
  return acc;
}

template <class AreaBound>
mesh_statistics compute_statistics_impl(const triangle_mesh& m, const AreaBound& bound_at) {
  const statistics_accumulator acc = accumulate_statistics(m, bound_at);
  mesh_statistics s;
  s.triangles = m.triangles.size();
  s.vertices = m.vertices.size();
  s.min_angle_deg = s.triangles == 0 ? 0.0 : acc.min_angle;
  s.max_angle_deg = acc.max_angle;
  s.max_ratio = acc.max_ratio;
  s.max_area = acc.max_area;
  s.max_area_ratio = acc.max_area_ratio;
  s.angle_histogram = acc.histogram;
  s.area = acc.area;
  return s;
}

} // namespace pdd::detail
