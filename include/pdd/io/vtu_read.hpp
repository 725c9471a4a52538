/// \file vtu_read.hpp
/// Readers for pdd's own VTK XML output: one .vtu piece (pdd::write_vtu) and the .pvtu index
/// over pieces (pdd::write_pvtu), e.g. a per-subdomain mesh of `pdd-mesh
/// --output-per-subdomain DIR`. They read exactly what pdd writes (appended raw data, UInt64
/// block headers, this machine's byte order) and refuse anything else with a clear error.
#pragma once

#include <pdd/core/triangle_mesh.hpp>
#include <pdd/errors.hpp>
#include <pdd/io/detail/vtu_read.hpp>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace pdd {

namespace detail {

/// Triangles from connectivity, offsets and types, each checked (3 * (i + 1), VTK triangle 5,
/// vertex index < n).
template <class Index>
void fill_vtu_triangles(const std::filesystem::path& path, std::ifstream& in,
                        const vtu_read_header_info& h, const char* type, triangle_mesh& m) {
  const auto conn = read_vtu_array<Index>(path, in, h, "connectivity", type, 3 * h.cells);
  const auto offsets = read_vtu_array<Index>(path, in, h, "offsets", type, h.cells);
  const auto types = read_vtu_array<std::uint8_t>(path, in, h, "types", "UInt8", h.cells);
  m.triangles.resize(static_cast<std::size_t>(h.cells));
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    if (types[t] != 5 || offsets[t] != static_cast<Index>(3 * (t + 1)))
      throw vtu_error(path, "cell " + std::to_string(t) + " is not a triangle");
    for (int k = 0; k < 3; ++k) {
      const Index v = conn[3 * t + static_cast<std::size_t>(k)];
      if (v < 0 || static_cast<std::uint64_t>(v) >= h.points)
        throw vtu_error(path, "cell " + std::to_string(t) + " refers to missing point " +
                                  std::to_string(v));
      m.triangles[t][static_cast<std::size_t>(k)] = static_cast<index_t>(v);
    }
  }
}

} // namespace detail

/// Reads a .vtu piece written by pdd::write_vtu: vertices (z must be 0, x and y finite),
/// triangles, vertex_markers (point data "vertex_marker") and triangle_markers (cell data
/// "subdomain"); segments stay empty (a .vtu carries none).
/// \throws pdd::error "path: what is wrong" for a file that cannot be opened, is not a VTK
/// UnstructuredGrid in pdd's layout, is truncated (every block's size is checked against the
/// file size before it is read) or holds a non-triangle cell, a bad vertex index or a
/// non-finite coordinate. Never reads past the end of the file.
/// Complexity: linear in the file size; memory: the mesh. Thread-safety: reentrant.
inline triangle_mesh read_vtu(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw detail::vtu_error(path, "cannot open for reading");
  const detail::vtu_read_header_info h = detail::read_vtu_header(path, in);
  triangle_mesh m;
  m.vertex_markers =
      detail::read_vtu_array<std::int32_t>(path, in, h, "vertex_marker", "Int32", h.points);
  m.triangle_markers =
      detail::read_vtu_array<std::int32_t>(path, in, h, "subdomain", "Int32", h.cells);
  const auto xyz = detail::read_vtu_array<double>(path, in, h, "Points", "Float64", 3 * h.points);
  m.vertices.resize(static_cast<std::size_t>(h.points));
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    const double x = xyz[3 * i], y = xyz[3 * i + 1], z = xyz[3 * i + 2];
    if (!std::isfinite(x) || !std::isfinite(y) || z != 0.0)
      throw detail::vtu_error(path, "point " + std::to_string(i) +
                                        " has a non-finite coordinate or z != 0");
    m.vertices[i] = {x, y};
  }
  const std::string& index_type = h.array(path, "connectivity").type;
  if (index_type == "Int32")
    detail::fill_vtu_triangles<std::int32_t>(path, in, h, "Int32", m);
  else
    detail::fill_vtu_triangles<std::int64_t>(path, in, h, "Int64", m);
  return m;
}

/// Reads a .pvtu index written by pdd::write_pvtu: the paths of its pieces, in file order,
/// resolved against the .pvtu's folder.
/// \throws pdd::error "path: what is wrong" when the file cannot be read, is not a VTK
/// PUnstructuredGrid in this machine's byte order, lists no piece or a piece without a Source.
/// Complexity: linear in the file size. Thread-safety: reentrant.
inline std::vector<std::filesystem::path> read_pvtu(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw detail::vtu_error(path, "cannot open for reading");
  std::ostringstream text;
  text << in.rdbuf();
  const std::string xml = text.str();
  detail::check_vtkfile_tag(path, xml, "PUnstructuredGrid");
  std::vector<std::filesystem::path> pieces;
  for (const std::string_view tag : detail::xml_tags(xml, "Piece")) {
    const auto source = detail::xml_attribute(tag, "Source");
    const auto name = source ? detail::xml_unescape(*source) : std::nullopt;
    if (!name || name->empty())
      throw detail::vtu_error(path, "a <Piece> has no readable Source attribute");
    pieces.push_back(path.parent_path() / *name);
  }
  if (pieces.empty()) throw detail::vtu_error(path, "lists no <Piece>");
  return pieces;
}

} // namespace pdd
