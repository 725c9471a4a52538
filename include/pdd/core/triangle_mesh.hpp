/// \file triangle_mesh.hpp
/// pdd::triangle_mesh: the mesh value type produced by kernels, pipelines and sinks.
#pragma once

#include <pdd/core/point.hpp>

#include <array>
#include <vector>

namespace pdd {

/// A mesh edge that lies on an input segment (or an interface), with its marker.
struct mesh_edge {
  /// First end: an index in triangle_mesh::vertices.
  index_t a = 0;
  /// Second end: an index in triangle_mesh::vertices.
  index_t b = 0;
  /// The boundary marker of the input segment (or interface) the edge lies on.
  int marker = 0;
};

/// A triangle mesh: vertices, counter-clockwise triangles, per-vertex and per-triangle markers
/// (the triangle marker is the subdomain id in decoupled meshes, 0 otherwise), and the edges
/// that lie on input segments with their segment markers.
struct triangle_mesh {
  /// The vertices; triangles and segments refer to them by index.
  std::vector<point> vertices;
  std::vector<int> vertex_markers;               ///< same size as vertices
  std::vector<std::array<index_t, 3>> triangles; ///< counter-clockwise
  std::vector<int> triangle_markers;             ///< same size as triangles
  std::vector<mesh_edge> segments;               ///< mesh edges on input segments

  /// The number of vertices, vertices.size().
  std::size_t num_vertices() const noexcept { return vertices.size(); }
  /// The number of triangles, triangles.size().
  std::size_t num_triangles() const noexcept { return triangles.size(); }
};

} // namespace pdd
