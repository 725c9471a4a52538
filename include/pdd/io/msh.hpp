/// \file msh.hpp
/// Gmsh MSH 4.1 ASCII output of a pdd::triangle_mesh (read by Gmsh and meshio).
#pragma once

#include <pdd/core/triangle_mesh.hpp>
#include <pdd/io/atomic_file.hpp>
#include <pdd/io/detail/mesh.hpp>
#include <pdd/io/detail/msh.hpp>

#include <filesystem>
#include <ostream>
#include <span>
#include <vector>

namespace pdd {

/// Writes the mesh as a Gmsh MSH 4.1 ASCII file, atomically.
///
/// Layout: `$MeshFormat 4.1 0 8`; `$Entities` with one surface entity per distinct triangle
/// marker (tags 1, 2, ... in increasing marker order; an ordinary mesh has the single surface
/// 1) and, when the mesh has segments, one curve entity per distinct segment marker; each
/// entity carries its marker as its one physical tag, so meshio's "gmsh:physical" cell data is
/// the subdomain for triangles and the boundary marker for lines. `$Nodes`: one block (dim 2,
/// surface 1), node tag = vertex index + 1. `$Elements`: triangles (type 2) grouped by surface,
/// tag = triangle index + 1; boundary lines (type 1) grouped by curve, tag = the triangle count +
/// segment index + 1. Coordinates are written in shortest round-trip form, z = 0.
/// With `region_attributes` (one per triangle: pdd::region_attributes) the surfaces group the
/// triangles by attribute instead, and each surface's physical tag is its attribute (so
/// meshio's "gmsh:physical" is the region); the attributes must then be integers.
/// \throws pdd::error naming the path for an inconsistent mesh, region attributes that are
///   not one per triangle or not integers, or a failed write.
/// Complexity: O(n log m) for m distinct markers. Thread-safety: reentrant.
inline void write_msh(const std::filesystem::path& path, const triangle_mesh& mesh,
                      std::span<const double> region_attributes = {}) {
  detail::check_mesh_for_writing(mesh, path);
  detail::check_region_attributes(mesh, region_attributes, path);
  const std::vector<int> tags = detail::msh_region_tags(region_attributes, path);
  write_file_atomically(path, [&](std::ostream& os) { detail::write_msh_stream(os, mesh, tags); });
}

} // namespace pdd
