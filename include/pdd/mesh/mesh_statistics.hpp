/// \file mesh_statistics.hpp
/// pdd::mesh_statistics, the result of pdd::compute_statistics (mesh/quality.hpp).
#pragma once

#include <array>
#include <cstddef>

namespace pdd {

/// Quality statistics of a triangle mesh.
struct mesh_statistics {
  /// The number of triangles measured (0: an empty mesh, every other field 0).
  std::size_t triangles = 0;
  /// The number of vertices of the mesh.
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

} // namespace pdd
