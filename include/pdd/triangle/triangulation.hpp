/// \file triangulation.hpp
/// pdd::triangle::triangulate_options and pdd::triangle::triangulation: the options and the
/// result of pdd::triangle::triangulate (triangle/triangulate.hpp).
#pragma once

#include <pdd/core/triangle_mesh.hpp>
#include <pdd/pipeline/statistics.hpp>

#include <array>
#include <cstddef>
#include <vector>

namespace pdd::triangle {

/// pdd's own knobs beside the switches.
struct triangulate_options {
  unsigned threads = 0;       ///< threads of pdd::generate (0: all cores)
  std::size_t subdomains = 0; ///< N of every component (0: automatic, 1: monolithic)
};

/// The mesh and the tables Triangle's outputs hold.
struct triangulation {
  /// The mesh: input vertices first, in input order (as Triangle numbers them), then the
  /// Steiner vertices; triangles counter-clockwise; segments the edges on input segments.
  triangle_mesh mesh;
  /// Switch A: the regional attribute of every triangle (0 where no region seed lies).
  std::vector<double> triangle_attributes;
  /// Switch n: the triangle across from vertex i of triangle t, -1 on the boundary.
  std::vector<std::array<long long, 3>> neighbors;
  /// One pdd::generate run per meshed part (the whole domain, or one per component when
  /// regional area bounds differ).
  std::vector<generate_statistics> runs;
  std::size_t jettisoned_vertices = 0; ///< switch j
};

} // namespace pdd::triangle
