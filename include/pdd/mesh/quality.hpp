/// \file quality.hpp
/// pdd::mesh_statistics and pdd::compute_statistics: angles, radius-edge ratios, areas and an
/// angle histogram of a triangle mesh.
#pragma once

#include <pdd/concepts/sizing_field.hpp>
#include <pdd/core/thread_sanitizer.hpp>
#include <pdd/core/triangle_measures.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/sizing/uniform.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

namespace pdd {

/// Quality statistics of a triangle mesh.
struct mesh_statistics {
  std::size_t triangles = 0;
  std::size_t vertices = 0;
  double min_angle_deg = 0.0; ///< smallest triangle angle (0 for an empty mesh)
  double max_angle_deg = 0.0; ///< largest triangle angle
  double max_ratio = 0.0;     ///< largest circumradius / shortest edge
  double max_area = 0.0;      ///< largest triangle area
  /// Largest area / (area bound at the centroid); 0 without a sizing field or when unbounded.
  double max_area_ratio = 0.0;
  /// Angles of all triangles in 1-degree bins: bin k counts angles in [k, k + 1) degrees.
  std::array<std::size_t, 180> angle_histogram{};
  double area = 0.0; ///< total area (sum of triangle areas)
};

namespace detail {

struct statistics_accumulator {
  double min_angle = std::numeric_limits<double>::infinity();
  double max_angle = 0.0;
  double max_ratio = 0.0;
  double max_area = 0.0;
  double max_area_ratio = 0.0;
  double area = 0.0;
  std::array<std::size_t, 180> histogram{};

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

template <class AreaBound>
mesh_statistics compute_statistics_impl(const triangle_mesh& m, const AreaBound& bound_at) {
  using range = tbb::blocked_range<std::size_t>;
  const detail::tsan_fork_join fork_join;
  const auto body = [&](const range& r, statistics_accumulator acc) {
    pdd::detail::tsan_fork_join::task_begins();
    const auto task = fork_join.task();
    for (std::size_t t = r.begin(); t != r.end(); ++t) {
      const auto& tri = m.triangles[t];
      const point& a = m.vertices[tri[0]];
      const point& b = m.vertices[tri[1]];
      const point& c = m.vertices[tri[2]];
      for (const double angle : triangle_angles_deg(a, b, c)) {
        acc.min_angle = std::min(acc.min_angle, angle);
        acc.max_angle = std::max(acc.max_angle, angle);
        const auto bin = static_cast<std::size_t>(std::clamp(std::floor(angle), 0.0, 179.0));
        ++acc.histogram[bin];
      }
      acc.max_ratio = std::max(acc.max_ratio, radius_edge_ratio(a, b, c));
      const double area = triangle_area(a, b, c);
      acc.max_area = std::max(acc.max_area, area);
      acc.area += area;
      const double bound = bound_at(triangle_centroid(a, b, c));
      if (!std::isinf(bound)) acc.max_area_ratio = std::max(acc.max_area_ratio, area / bound);
    }
    return acc;
  };
  // parallel_deterministic_reduce splits and joins the same way for any thread count, so the
  // floating-point sum of areas is bitwise reproducible.
  const statistics_accumulator acc = tbb::parallel_deterministic_reduce(
      range(0, m.triangles.size(), statistics_grain), statistics_accumulator{}, body,
      [&](statistics_accumulator x, const statistics_accumulator& y) {
        pdd::detail::tsan_fork_join::task_begins();
        const auto task = fork_join.task();
        x.join(y);
        return x;
      });
  fork_join.join();
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

} // namespace detail

/// Computes the statistics of a mesh, with the area of each triangle compared to the bound
/// `area_bound.area_at(centroid)`.
/// \tparam S a SizingField.
/// \pre Triangle vertex indices are < m.vertices.size().
/// Complexity O(triangles), parallel (TBB); the result is bitwise the same for any number of
/// threads. Thread-safe.
template <SizingField S>
mesh_statistics compute_statistics(const triangle_mesh& m, const S& area_bound) {
  return detail::compute_statistics_impl(
      m, [&](const point& p) { return static_cast<double>(area_bound.area_at(p)); });
}

/// Computes the statistics of a mesh without a sizing field (max_area_ratio = 0).
/// Complexity O(triangles), parallel, deterministic. Thread-safe.
inline mesh_statistics compute_statistics(const triangle_mesh& m) {
  return detail::compute_statistics_impl(
      m, [](const point&) { return std::numeric_limits<double>::infinity(); });
}

} // namespace pdd
