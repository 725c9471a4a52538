/// \file triangle_files.hpp
/// Triangle's mesh output formats for a pdd::triangle_mesh: .node (vertices), .ele
/// (triangles) and a .poly holding the mesh's boundary segments over the .node's vertices.
/// Formats: https://www.cs.cmu.edu/~quake/triangle.node.html, triangle.ele.html.
#pragma once

#include <pdd/io/detail/mesh.hpp>
#include <pdd/io/detail/text.hpp>
#include <pdd/io/atomic_file.hpp>
#include <pdd/core/triangle_mesh.hpp>

#include <filesystem>
#include <ostream>

namespace pdd {

/// Writes the mesh's vertices as a Triangle .node file, atomically: header
/// `<#vertices> 2 0 1`, then `<id> <x> <y> <vertex marker>` with 1-based ids (Triangle's
/// default) and coordinates in shortest round-trip form.
/// \throws pdd::error naming the path for an inconsistent mesh or a failed write.
/// Complexity: linear. Thread-safety: reentrant.
inline void write_node(const std::filesystem::path& path, const triangle_mesh& mesh) {
  detail::check_mesh_for_writing(mesh, path);
  write_file_atomically(path, [&](std::ostream& os) {
    detail::text_sink out(os);
    out.integer(mesh.vertices.size()).put(" 2 0 1\n");
    for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
      out.integer(i + 1).put(' ').num(mesh.vertices[i].x).put(' ').num(mesh.vertices[i].y);
      out.put(' ').integer(detail::vertex_marker(mesh, i)).put('\n');
    }
    out.flush();
  });
}

/// Writes the mesh's triangles as a Triangle .ele file, atomically: header `<#triangles> 3 1`,
/// then `<id> <v0> <v1> <v2> <attribute>` with 1-based ids, counter-clockwise vertices and the
/// triangle marker (the subdomain id in decoupled meshes) as the one triangle attribute.
/// \throws pdd::error naming the path for an inconsistent mesh or a failed write.
/// Complexity: linear. Thread-safety: reentrant.
inline void write_ele(const std::filesystem::path& path, const triangle_mesh& mesh) {
  detail::check_mesh_for_writing(mesh, path);
  write_file_atomically(path, [&](std::ostream& os) {
    detail::text_sink out(os);
    out.integer(mesh.triangles.size()).put(" 3 1\n");
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const auto& tri = mesh.triangles[t];
      out.integer(t + 1);
      for (const index_t v : tri)
        out.put(' ').integer(std::size_t{v} + 1);
      out.put(' ').integer(detail::triangle_marker(mesh, t)).put('\n');
    }
    out.flush();
  });
}

/// Writes the mesh's boundary segments (mesh.segments) as a Triangle .poly file that refers
/// to the .node file of the same stem (vertex count 0, as Triangle's own output .poly files
/// do), atomically: `0 2 0 1`, `<#segments> 1`, `<id> <a> <b> <marker>` (1-based), `0` holes.
/// read_poly() of this file together with write_node()'s file gives back the vertices, vertex
/// markers and segments bit for bit.
/// \throws pdd::error naming the path for an inconsistent mesh or a failed write.
/// Complexity: linear. Thread-safety: reentrant.
inline void write_mesh_poly(const std::filesystem::path& path, const triangle_mesh& mesh) {
  detail::check_mesh_for_writing(mesh, path);
  write_file_atomically(path, [&](std::ostream& os) {
    detail::text_sink out(os);
    out.put("# vertices are in the .node file of the same name\n0 2 0 1\n");
    out.integer(mesh.segments.size()).put(" 1\n");
    for (std::size_t s = 0; s < mesh.segments.size(); ++s) {
      const mesh_edge& e = mesh.segments[s];
      out.integer(s + 1).put(' ').integer(std::size_t{e.a} + 1).put(' ');
      out.integer(std::size_t{e.b} + 1).put(' ').integer(e.marker).put('\n');
    }
    out.put("0\n");
    out.flush();
  });
}

/// Writes `<stem>.node`, `<stem>.ele` and `<stem>.poly` beside each other (stem = path without
/// its extension), each atomically.
/// \throws pdd::error as write_node / write_ele / write_mesh_poly.
inline void write_triangle_files(const std::filesystem::path& path, const triangle_mesh& mesh) {
  std::filesystem::path stem = path;
  stem.replace_extension();
  write_node(std::filesystem::path(stem).concat(".node"), mesh);
  write_ele(std::filesystem::path(stem).concat(".ele"), mesh);
  write_mesh_poly(std::filesystem::path(stem).concat(".poly"), mesh);
}

} // namespace pdd
