/// \file msh.hpp
/// Gmsh MSH 4.1 ASCII output of a pdd::triangle_mesh (read by Gmsh and meshio).
#pragma once

#include <pdd/io/detail/mesh.hpp>
#include <pdd/io/detail/text.hpp>
#include <pdd/io/atomic_file.hpp>
#include <pdd/core/triangle_mesh.hpp>

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <limits>
#include <map>
#include <ostream>
#include <vector>

namespace pdd {

namespace detail {

/// One MSH entity: the elements (triangle or segment indices) that carry one marker.
struct msh_entity {
  int marker = 0;
  std::vector<std::size_t> elements;
  double box[4] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                   -std::numeric_limits<double>::infinity(),
                   -std::numeric_limits<double>::infinity()};
  void grow(point p) {
    box[0] = std::min(box[0], p.x);
    box[1] = std::min(box[1], p.y);
    box[2] = std::max(box[2], p.x);
    box[3] = std::max(box[3], p.y);
  }
};

/// Groups elements by marker, in increasing marker order (deterministic).
template <class MarkerOf, class Grow>
std::vector<msh_entity> group_by_marker(std::size_t count, const MarkerOf& marker_of,
                                        const Grow& grow) {
  std::map<int, msh_entity> by_marker;
  for (std::size_t i = 0; i < count; ++i) {
    msh_entity& e = by_marker[marker_of(i)];
    e.elements.push_back(i);
    grow(e, i);
  }
  std::vector<msh_entity> out;
  for (auto& [marker, e] : by_marker) {
    e.marker = marker;
    out.push_back(std::move(e));
  }
  return out;
}

inline void write_msh_entity(text_sink& out, std::size_t tag, const msh_entity& e) {
  out.integer(tag);
  for (int k = 0; k < 4; ++k) {
    if (k == 2) out.put(" 0"); // minZ
    out.put(' ').num(e.box[k]);
  }
  out.put(" 0 1 ").integer(e.marker).put(" 0\n"); // maxZ, one physical tag, no boundary
}

inline void write_msh_stream(std::ostream& os, const triangle_mesh& mesh) {
  const std::size_t n = mesh.vertices.size();
  const std::size_t nt = mesh.triangles.size();
  const std::size_t ns = mesh.segments.size();
  const auto surfaces = group_by_marker(
      nt, [&](std::size_t t) { return triangle_marker(mesh, t); },
      [&](msh_entity& e, std::size_t t) {
        for (const index_t v : mesh.triangles[t])
          e.grow(mesh.vertices[v]);
      });
  const auto curves = group_by_marker(
      ns, [&](std::size_t s) { return mesh.segments[s].marker; },
      [&](msh_entity& e, std::size_t s) {
        e.grow(mesh.vertices[mesh.segments[s].a]);
        e.grow(mesh.vertices[mesh.segments[s].b]);
      });

  text_sink out(os);
  out.put("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n");
  // Entities: no points, one curve per segment marker, one surface per triangle marker (a mesh
  // with one marker has exactly one surface, tag 1); the physical tag is the marker.
  out.put("$Entities\n0 ").integer(curves.size()).put(' ').integer(surfaces.size()).put(" 0\n");
  for (std::size_t c = 0; c < curves.size(); ++c)
    write_msh_entity(out, c + 1, curves[c]);
  for (std::size_t s = 0; s < surfaces.size(); ++s)
    write_msh_entity(out, s + 1, surfaces[s]);
  out.put("$EndEntities\n");

  // Nodes: one block on surface 1, tags 1..n.
  out.put("$Nodes\n");
  if (n == 0) {
    out.put("0 0 0 0\n");
  } else {
    out.put("1 ").integer(n).put(" 1 ").integer(n).put('\n');
    out.put("2 1 0 ").integer(n).put('\n');
    for (std::size_t i = 0; i < n; ++i)
      out.integer(i + 1).put('\n');
    for (const point& p : mesh.vertices)
      out.num(p.x).put(' ').num(p.y).put(" 0\n");
  }
  out.put("$EndNodes\n");

  // Elements: triangle i has tag i + 1, segment j has tag nt + j + 1.
  out.put("$Elements\n").integer(surfaces.size() + curves.size()).put(' ').integer(nt + ns);
  out.put(' ').integer(nt + ns == 0 ? 0 : 1).put(' ').integer(nt + ns).put('\n');
  for (std::size_t s = 0; s < surfaces.size(); ++s) {
    out.put("2 ").integer(s + 1).put(" 2 ").integer(surfaces[s].elements.size()).put('\n');
    for (const std::size_t t : surfaces[s].elements) {
      out.integer(t + 1);
      for (const index_t v : mesh.triangles[t])
        out.put(' ').integer(std::size_t{v} + 1);
      out.put('\n');
    }
  }
  for (std::size_t c = 0; c < curves.size(); ++c) {
    out.put("1 ").integer(c + 1).put(" 1 ").integer(curves[c].elements.size()).put('\n');
    for (const std::size_t j : curves[c].elements) {
      const mesh_edge& e = mesh.segments[j];
      out.integer(nt + j + 1).put(' ').integer(std::size_t{e.a} + 1).put(' ');
      out.integer(std::size_t{e.b} + 1).put('\n');
    }
  }
  out.put("$EndElements\n");
  out.flush();
}

} // namespace detail

/// Writes the mesh as a Gmsh MSH 4.1 ASCII file, atomically.
///
/// Layout: `$MeshFormat 4.1 0 8`; `$Entities` with one surface entity per distinct triangle
/// marker (tags 1, 2, ... in increasing marker order; an ordinary mesh has the single surface
/// 1) and, when the mesh has segments, one curve entity per distinct segment marker; each
/// entity carries its marker as its one physical tag, so meshio's "gmsh:physical" cell data is
/// the subdomain for triangles and the boundary marker for lines. `$Nodes`: one block (dim 2,
/// surface 1), node tag = vertex index + 1. `$Elements`: triangles (type 2) grouped by surface,
/// tag = triangle index + 1; boundary lines (type 1) grouped by curve, tag = #triangles +
/// segment index + 1. Coordinates are written in shortest round-trip form, z = 0.
/// \throws pdd::error naming the path for an inconsistent mesh or a failed write.
/// Complexity: O(n log m) for m distinct markers. Thread-safety: reentrant.
inline void write_msh(const std::filesystem::path& path, const triangle_mesh& mesh) {
  detail::check_mesh_for_writing(mesh, path);
  write_file_atomically(path, [&](std::ostream& os) { detail::write_msh_stream(os, mesh); });
}

} // namespace pdd
