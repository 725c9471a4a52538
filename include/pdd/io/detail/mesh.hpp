/// \file mesh.hpp
/// Implementation details shared by pdd's mesh writers: the consistency check every writer
/// runs before it creates a file, and marker look-ups that tolerate empty marker arrays.
#pragma once

#include <pdd/core/triangle_mesh.hpp>
#include <pdd/errors.hpp>

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>

namespace pdd::detail {

/// Throws pdd::error naming `path` unless the mesh is consistent enough to be written: marker
/// arrays empty or of the right size, every triangle and segment index a vertex, every
/// coordinate finite. Complexity: linear.
inline void check_mesh_for_writing(const triangle_mesh& m, const std::filesystem::path& path) {
  const std::string where = "cannot write '" + path.string() + "': ";
  const std::size_t n = m.vertices.size();
  if (!m.vertex_markers.empty() && m.vertex_markers.size() != n)
    throw error(where + "vertex_markers and vertices differ in size");
  if (!m.triangle_markers.empty() && m.triangle_markers.size() != m.triangles.size())
    throw error(where + "triangle_markers and triangles differ in size");
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(m.vertices[i].x) || !std::isfinite(m.vertices[i].y))
      throw error(where + "vertex " + std::to_string(i) + " has a NaN or infinite coordinate");
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (const index_t v : m.triangles[t])
      if (v >= n)
        throw error(where + "triangle " + std::to_string(t) + " refers to missing vertex " +
                    std::to_string(v));
  for (std::size_t s = 0; s < m.segments.size(); ++s)
    if (m.segments[s].a >= n || m.segments[s].b >= n)
      throw error(where + "segment " + std::to_string(s) + " refers to a missing vertex");
}

/// Checks that region attributes (empty: none) are one per triangle.
/// \throws pdd::error naming the path otherwise.
inline void check_region_attributes(const triangle_mesh& m, std::span<const double> attributes,
                                    const std::filesystem::path& path) {
  if (!attributes.empty() && attributes.size() != m.triangles.size())
    throw error("cannot write '" + path.string() + "': " + std::to_string(attributes.size()) +
                " region attributes for " + std::to_string(m.triangles.size()) + " triangles");
}

/// Marker of vertex i (0 when the mesh has no vertex markers).
inline int vertex_marker(const triangle_mesh& m, std::size_t i) noexcept {
  return m.vertex_markers.empty() ? 0 : m.vertex_markers[i];
}
/// Marker of triangle t (0 when the mesh has no triangle markers).
inline int triangle_marker(const triangle_mesh& m, std::size_t t) noexcept {
  return m.triangle_markers.empty() ? 0 : m.triangle_markers[t];
}

} // namespace pdd::detail
