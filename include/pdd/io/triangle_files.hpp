/// \file triangle_files.hpp
/// Triangle's mesh output formats for a pdd::triangle_mesh: .node (vertices), .ele
/// (triangles) and a .poly holding the mesh's boundary segments over the .node's vertices;
/// .neigh, .edge (switch e) and a Voronoi diagram's .v.node and .v.edge (switch v).
/// Formats: https://www.cs.cmu.edu/~quake/triangle.node.html, triangle.ele.html.
#pragma once

#include <pdd/core/triangle_mesh.hpp>
#include <pdd/io/atomic_file.hpp>
#include <pdd/io/detail/mesh.hpp>
#include <pdd/io/detail/text.hpp>

#include <array>
#include <filesystem>
#include <ostream>
#include <span>
#include <string>
#include <vector>

namespace pdd {

/// How the Triangle-format writers number and annotate (Triangle's switches z, B, A).
struct triangle_format {
  std::size_t first_index = 1; ///< 1 (Triangle's default) or 0 (switch z)
  bool markers = true;         ///< vertex and segment marker columns (switch B: false)
  /// .ele: the triangle marker as the one attribute column (pdd's default); false: no
  /// column unless attributes are passed to write_ele.
  bool marker_attribute = true;
};

/// Writes the mesh's vertices as a Triangle .node file, atomically: header
/// `<#vertices> 2 0 1`, then `<id> <x> <y> <vertex marker>` with 1-based ids (Triangle's
/// default) and coordinates in shortest round-trip form.
/// \throws pdd::error naming the path for an inconsistent mesh or a failed write.
/// Complexity: linear. Thread-safety: reentrant.
/// `format` picks the first id and whether the marker column is written; `attributes`
/// (`attribute_count` per vertex, vertex by vertex) are written after the coordinates.
/// \throws pdd::error also when attributes is not attribute_count values per vertex.
inline void write_node(const std::filesystem::path& path, const triangle_mesh& mesh,
                       const triangle_format& format = {}, std::span<const double> attributes = {},
                       std::size_t attribute_count = 0) {
  detail::check_mesh_for_writing(mesh, path);
  if (attributes.size() != attribute_count * mesh.vertices.size())
    throw error("cannot write '" + path.string() + "': " + std::to_string(attributes.size()) +
                " vertex attributes for " + std::to_string(mesh.vertices.size()) + " vertices x " +
                std::to_string(attribute_count));
  write_file_atomically(path, [&](std::ostream& os) {
    detail::text_sink out(os);
    out.integer(mesh.vertices.size()).put(" 2 ").integer(attribute_count);
    out.put(format.markers ? " 1\n" : " 0\n");
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
      out.integer(i + format.first_index).put(' ').num(mesh.vertices[i].x).put(' ');
      out.num(mesh.vertices[i].y);
      for (std::size_t k = 0; k < attribute_count; ++k)
        out.put(' ').num(attributes[i * attribute_count + k]);
      if (format.markers) out.put(' ').integer(detail::vertex_marker(mesh, i));
      out.put('\n');
    }
    out.flush();
  });
}

/// Writes the mesh's triangles as a Triangle .ele file, atomically: header `<#triangles> 3 1`,
/// then `<id> <v0> <v1> <v2> <attribute>` with 1-based ids, counter-clockwise vertices and the
/// triangle marker (the subdomain id in decoupled meshes) as the one triangle attribute.
/// \throws pdd::error naming the path for an inconsistent mesh or a failed write.
/// Complexity: linear. Thread-safety: reentrant.
/// `format` picks the first id and the attribute column: `attributes` (one value per
/// triangle, e.g. Triangle's regional attributes) when given, else the marker when
/// format.marker_attribute, else none (header `<#triangles> 3 0`).
/// `extra_nodes` (Triangle's -o2): per triangle its nodes 4-6, written after the corners
/// (header `<#triangles> 6 ...`).
/// \throws pdd::error also when attributes or extra_nodes is non-empty and not one entry per
/// triangle.
inline void write_ele(const std::filesystem::path& path, const triangle_mesh& mesh,
                      const triangle_format& format = {}, std::span<const double> attributes = {},
                      std::span<const std::array<index_t, 3>> extra_nodes = {}) {
  detail::check_mesh_for_writing(mesh, path);
  const auto check_count = [&](std::size_t n, const char* what) {
    if (n != 0 && n != mesh.triangles.size())
      throw error("cannot write '" + path.string() + "': " + std::to_string(n) + " " + what +
                  " for " + std::to_string(mesh.triangles.size()) + " triangles");
  };
  check_count(attributes.size(), "triangle attributes");
  check_count(extra_nodes.size(), "six-node triangles");
  for (const auto& nodes : extra_nodes)
    for (const index_t v : nodes)
      if (v >= mesh.vertices.size())
        throw error("cannot write '" + path.string() + "': node " + std::to_string(v) +
                    " of a six-node triangle is not a vertex");
  const bool column = !attributes.empty() || format.marker_attribute;
  write_file_atomically(path, [&](std::ostream& os) {
    detail::text_sink out(os);
    out.integer(mesh.triangles.size()).put(extra_nodes.empty() ? " 3" : " 6");
    out.put(column ? " 1\n" : " 0\n");
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      out.integer(t + format.first_index);
      for (const index_t v : mesh.triangles[t])
        out.put(' ').integer(std::size_t{v} + format.first_index);
      if (!extra_nodes.empty())
        for (const index_t v : extra_nodes[t])
          out.put(' ').integer(std::size_t{v} + format.first_index);
      if (!attributes.empty())
        out.put(' ').num(attributes[t]);
      else if (column)
        out.put(' ').integer(detail::triangle_marker(mesh, t));
      out.put('\n');
    }
    out.flush();
  });
}

/// Writes the mesh's boundary segments (mesh.segments) as a Triangle .poly file that refers
/// to the .node file of the same stem (vertex count 0, as Triangle's own output .poly files
/// do), atomically: `0 2 0 1`, `<#segments> 1`, `<id> <a> <b> <marker>` (1-based), the holes.
/// read_poly() of this file together with write_node()'s file gives back the vertices, vertex
/// markers and segments bit for bit.
/// \throws pdd::error naming the path for an inconsistent mesh or a failed write.
/// Complexity: linear. Thread-safety: reentrant.
/// `format` picks the first id and the marker column; `holes` are written in the holes
/// section (Triangle copies the input's hole points there).
inline void write_mesh_poly(const std::filesystem::path& path, const triangle_mesh& mesh,
                            const triangle_format& format = {}, std::span<const point> holes = {}) {
  detail::check_mesh_for_writing(mesh, path);
  write_file_atomically(path, [&](std::ostream& os) {
    detail::text_sink out(os);
    out.put("# vertices are in the .node file of the same name\n");
    out.put(format.markers ? "0 2 0 1\n" : "0 2 0 0\n");
    out.integer(mesh.segments.size()).put(format.markers ? " 1\n" : " 0\n");
    const std::size_t f = format.first_index;
    for (std::size_t s = 0; s < mesh.segments.size(); ++s) {
      const mesh_edge& e = mesh.segments[s];
      out.integer(s + f).put(' ').integer(std::size_t{e.a} + f).put(' ');
      out.integer(std::size_t{e.b} + f);
      if (format.markers) out.put(' ').integer(e.marker);
      out.put('\n');
    }
    out.integer(holes.size()).put('\n');
    for (std::size_t h = 0; h < holes.size(); ++h)
      out.integer(h + f).put(' ').num(holes[h].x).put(' ').num(holes[h].y).put('\n');
    out.flush();
  });
}

/// Writes a Triangle .neigh file, atomically: header `<#triangles> 3`, then
/// `<id> <n0> <n1> <n2>`, neighbour i across from vertex i, -1 on the boundary (Triangle
/// writes -1 whatever the first index).
/// \throws pdd::error when writing fails.
inline void write_neigh(const std::filesystem::path& path,
                        std::span<const std::array<long long, 3>> neighbors,
                        const triangle_format& format = {}) {
  write_file_atomically(path, [&](std::ostream& os) {
    detail::text_sink out(os);
    out.integer(neighbors.size()).put(" 3\n");
    const auto f = static_cast<long long>(format.first_index);
    for (std::size_t t = 0; t < neighbors.size(); ++t) {
      out.integer(t + format.first_index);
      for (const long long n : neighbors[t])
        out.put(' ').integer(n < 0 ? -1LL : n + f);
      out.put('\n');
    }
    out.flush();
  });
}

/// Writes a Triangle .edge file, atomically: header `<#edges> <1|0>`, then
/// `<id> <endpoint> <endpoint> [marker]` (the marker column unless format.markers is false).
/// \throws pdd::error when writing fails.
inline void write_edge(const std::filesystem::path& path, std::span<const mesh_edge> edges,
                       const triangle_format& format = {}) {
  write_file_atomically(path, [&](std::ostream& os) {
    detail::text_sink out(os);
    out.integer(edges.size()).put(format.markers ? " 1\n" : " 0\n");
    const std::size_t f = format.first_index;
    for (std::size_t e = 0; e < edges.size(); ++e) {
      out.integer(e + f).put(' ').integer(std::size_t{edges[e].a} + f).put(' ');
      out.integer(std::size_t{edges[e].b} + f);
      if (format.markers) out.put(' ').integer(edges[e].marker);
      out.put('\n');
    }
    out.flush();
  });
}

/// Writes a Voronoi diagram as Triangle's .v.node and .v.edge files, each atomically:
/// `<#vertices> 2 0 0` and `<id> <x> <y>`; `<#edges> 0` and `<id> <v> <w>` for a finite edge,
/// `<id> <v> -1 <dx> <dy>` for a ray (edge[1] < 0; direction from `directions`, one per edge).
/// \throws pdd::error for a direction count that is not the edge count, or a failed write.
inline void write_voronoi(const std::filesystem::path& node_path,
                          const std::filesystem::path& edge_path, std::span<const point> vertices,
                          std::span<const std::array<long long, 2>> edges,
                          std::span<const point> directions, const triangle_format& format = {}) {
  if (directions.size() != edges.size())
    throw error("cannot write '" + edge_path.string() + "': " + std::to_string(edges.size()) +
                " Voronoi edges with " + std::to_string(directions.size()) + " directions");
  const auto f = static_cast<long long>(format.first_index);
  write_file_atomically(node_path, [&](std::ostream& os) {
    detail::text_sink out(os);
    out.integer(vertices.size()).put(" 2 0 0\n");
    for (std::size_t v = 0; v < vertices.size(); ++v)
      out.integer(v + format.first_index)
          .put(' ')
          .num(vertices[v].x)
          .put(' ')
          .num(vertices[v].y)
          .put('\n');
    out.flush();
  });
  write_file_atomically(edge_path, [&](std::ostream& os) {
    detail::text_sink out(os);
    out.integer(edges.size()).put(" 0\n");
    for (std::size_t e = 0; e < edges.size(); ++e) {
      out.integer(e + format.first_index).put(' ').integer(edges[e][0] + f).put(' ');
      if (edges[e][1] >= 0)
        out.integer(edges[e][1] + f);
      else
        out.put("-1 ").num(directions[e].x).put(' ').num(directions[e].y);
      out.put('\n');
    }
    out.flush();
  });
}

/// Writes `<stem>.node`, `<stem>.ele` and `<stem>.poly` beside each other (stem = path without
/// its extension), each atomically.
/// The .ele's attribute column holds `region_attributes` when given (one per triangle:
/// pdd::region_attributes), the triangle markers otherwise.
/// \throws pdd::error as write_node / write_ele / write_mesh_poly.
inline void write_triangle_files(const std::filesystem::path& path, const triangle_mesh& mesh,
                                 std::span<const double> region_attributes = {}) {
  detail::check_region_attributes(mesh, region_attributes, path); // before any file
  std::filesystem::path stem = path;
  stem.replace_extension();
  write_node(std::filesystem::path(stem).concat(".node"), mesh);
  write_ele(std::filesystem::path(stem).concat(".ele"), mesh, {}, region_attributes);
  write_mesh_poly(std::filesystem::path(stem).concat(".poly"), mesh);
}

} // namespace pdd
