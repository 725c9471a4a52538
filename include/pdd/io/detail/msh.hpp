/// \file msh.hpp
/// Implementation of pdd::write_msh: the entities (one per marker) and the $Entities, $Nodes
/// and $Elements sections of a Gmsh MSH 4.1 ASCII file.
#pragma once

#include <pdd/core/triangle_mesh.hpp>
#include <pdd/io/detail/mesh.hpp>
#include <pdd/io/detail/text.hpp>

#include <pdd/errors.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <limits>
#include <map>
#include <ostream>
#include <span>
#include <string>
#include <vector>

namespace pdd::detail {

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

/// $Entities: no points, one curve per segment marker, one surface per triangle marker (a mesh
/// with one marker has exactly one surface, tag 1); the physical tag is the marker.
inline void write_msh_entities(text_sink& out, const std::vector<msh_entity>& curves,
                               const std::vector<msh_entity>& surfaces) {
  out.put("$Entities\n0 ").integer(curves.size()).put(' ').integer(surfaces.size()).put(" 0\n");
  for (std::size_t c = 0; c < curves.size(); ++c)
    write_msh_entity(out, c + 1, curves[c]);
  for (std::size_t s = 0; s < surfaces.size(); ++s)
    write_msh_entity(out, s + 1, surfaces[s]);
  out.put("$EndEntities\n");
}

/// $Nodes: one block on surface 1, tags 1..n.
inline void write_msh_nodes(text_sink& out, const triangle_mesh& mesh) {
  const std::size_t n = mesh.vertices.size();
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
}

/// $Elements: triangle i has tag i + 1 (grouped by surface), segment j has tag nt + j + 1
/// (grouped by curve).
inline void write_msh_elements(text_sink& out, const triangle_mesh& mesh,
                               const std::vector<msh_entity>& curves,
                               const std::vector<msh_entity>& surfaces) {
  const std::size_t nt = mesh.triangles.size();
  const std::size_t ns = mesh.segments.size();
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
}

/// The physical tags of the triangles for region attributes (pdd::region_attributes): each
/// attribute itself, which must be an integer that fits an int.
/// \throws pdd::error naming the path, the triangle and the attribute otherwise.
inline std::vector<int> msh_region_tags(std::span<const double> attributes,
                                        const std::filesystem::path& path) {
  std::vector<int> tags(attributes.size());
  for (std::size_t t = 0; t < attributes.size(); ++t) {
    const double a = attributes[t];
    if (!(std::trunc(a) == a && a >= std::numeric_limits<int>::min() &&
          a <= std::numeric_limits<int>::max()))
      throw error("cannot write '" + path.string() + "': the region attribute " +
                  std::to_string(a) + " of triangle " + std::to_string(t) +
                  " is not an integer, and a .msh physical tag must be one (write .vtu or "
                  ".ele for real-valued attributes)");
    tags[t] = static_cast<int>(a);
  }
  return tags;
}

/// The MSH 4.1 ASCII text of the mesh (see pdd::write_msh for the layout); `surface_tags`:
/// the physical tag of every triangle (empty: the triangle markers).
inline void write_msh_stream(std::ostream& os, const triangle_mesh& mesh,
                             std::span<const int> surface_tags = {}) {
  const auto surfaces = group_by_marker(
      mesh.triangles.size(),
      [&](std::size_t t) {
        return surface_tags.empty() ? triangle_marker(mesh, t) : surface_tags[t];
      },
      [&](msh_entity& e, std::size_t t) {
        for (const index_t v : mesh.triangles[t])
          e.grow(mesh.vertices[v]);
      });
  const auto curves = group_by_marker(
      mesh.segments.size(), [&](std::size_t s) { return mesh.segments[s].marker; },
      [&](msh_entity& e, std::size_t s) {
        e.grow(mesh.vertices[mesh.segments[s].a]);
        e.grow(mesh.vertices[mesh.segments[s].b]);
      });
  text_sink out(os);
  out.put("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n");
  write_msh_entities(out, curves, surfaces);
  write_msh_nodes(out, mesh);
  write_msh_elements(out, mesh, curves, surfaces);
  out.flush();
}

} // namespace pdd::detail
