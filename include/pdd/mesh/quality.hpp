/// \file quality.hpp
/// pdd::mesh_statistics and pdd::compute_statistics: angles, radius-edge ratios, areas and an
/// angle histogram of a triangle mesh.
#pragma once

#include <pdd/concepts/sizing_field.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/mesh/detail/quality.hpp>
#include <pdd/mesh/mesh_statistics.hpp>
#include <pdd/sizing/uniform.hpp>

#include <limits>

namespace pdd {

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
