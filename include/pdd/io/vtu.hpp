/// \file vtu.hpp
/// VTK XML UnstructuredGrid output (.vtu, read by ParaView, VisIt and meshio) and the
/// parallel index (.pvtu) over per-subdomain pieces.
#pragma once

#include <pdd/io/detail/mesh.hpp>
#include <pdd/io/detail/text.hpp>
#include <pdd/errors.hpp>
#include <pdd/io/atomic_file.hpp>
#include <pdd/core/triangle_mesh.hpp>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace pdd {

namespace detail {

inline const char* vtk_byte_order() noexcept {
  return std::endian::native == std::endian::big ? "BigEndian" : "LittleEndian";
}

/// Writes one appended-data block: the UInt64 byte count, then count values value_at(i) of
/// type T in native byte order, through a bounded buffer.
template <class T, class F>
void write_vtk_block(std::ostream& os, std::size_t count, const F& value_at) {
  const std::uint64_t bytes = static_cast<std::uint64_t>(count) * sizeof(T);
  os.write(reinterpret_cast<const char*>(&bytes), sizeof bytes);
  constexpr std::size_t chunk = std::size_t{1} << 14;
  std::vector<T> buf;
  buf.reserve(std::min(count, chunk));
  for (std::size_t i = 0; i < count;) {
    buf.clear();
    const std::size_t end = std::min(count, i + chunk);
    for (; i < end; ++i)
      buf.push_back(value_at(i));
    os.write(reinterpret_cast<const char*>(buf.data()),
             static_cast<std::streamsize>(buf.size() * sizeof(T)));
  }
}

template <class Index>
void write_vtu_stream(std::ostream& os, const triangle_mesh& mesh, const char* index_type) {
  const std::size_t n = mesh.vertices.size();
  const std::size_t t = mesh.triangles.size();
  // Byte sizes of the appended blocks, in file order; each block has an 8-byte size header.
  const std::size_t sizes[] = {n * 4, t * 4, n * 3 * 8, t * 3 * sizeof(Index), t * sizeof(Index),
                               t};
  std::uint64_t off[6];
  std::uint64_t acc = 0;
  for (int k = 0; k < 6; ++k) {
    off[k] = acc;
    acc += 8 + sizes[k];
  }
  std::string h;
  h += "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"";
  h += vtk_byte_order();
  h += "\" header_type=\"UInt64\">\n  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"";
  append_integer(h, n);
  h += "\" NumberOfCells=\"";
  append_integer(h, t);
  h += "\">\n";
  const auto array = [&](const char* type, const char* name, int comps, std::uint64_t offset) {
    h += "        <DataArray type=\"";
    h += type;
    h += "\" Name=\"";
    h += name;
    if (comps > 1) {
      h += "\" NumberOfComponents=\"";
      append_integer(h, comps);
    }
    h += "\" format=\"appended\" offset=\"";
    append_integer(h, offset);
    h += "\"/>\n";
  };
  h += "      <PointData Scalars=\"vertex_marker\">\n";
  array("Int32", "vertex_marker", 1, off[0]);
  h += "      </PointData>\n      <CellData Scalars=\"subdomain\">\n";
  array("Int32", "subdomain", 1, off[1]);
  h += "      </CellData>\n      <Points>\n";
  array("Float64", "Points", 3, off[2]);
  h += "      </Points>\n      <Cells>\n";
  array(index_type, "connectivity", 1, off[3]);
  array(index_type, "offsets", 1, off[4]);
  array("UInt8", "types", 1, off[5]);
  h += "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n"
       "  <AppendedData encoding=\"raw\">\n   _";
  os.write(h.data(), static_cast<std::streamsize>(h.size()));

  write_vtk_block<std::int32_t>(os, n, [&](std::size_t i) { return vertex_marker(mesh, i); });
  write_vtk_block<std::int32_t>(os, t, [&](std::size_t i) { return triangle_marker(mesh, i); });
  write_vtk_block<double>(os, n * 3, [&](std::size_t i) {
    const point& p = mesh.vertices[i / 3];
    return i % 3 == 0 ? p.x : i % 3 == 1 ? p.y : 0.0;
  });
  write_vtk_block<Index>(
      os, t * 3, [&](std::size_t i) { return static_cast<Index>(mesh.triangles[i / 3][i % 3]); });
  write_vtk_block<Index>(os, t, [](std::size_t i) { return static_cast<Index>(3 * (i + 1)); });
  write_vtk_block<std::uint8_t>(os, t, [](std::size_t) { return std::uint8_t{5}; }); // triangle
  os << "\n  </AppendedData>\n</VTKFile>\n";
}

} // namespace detail

/// Writes the mesh as a VTK XML UnstructuredGrid (.vtu), atomically, in binary appended raw
/// encoding (header_type UInt64, native byte order declared): 3D points (z = 0), triangle
/// cells (VTK type 5), point data "vertex_marker" (Int32) and cell data "subdomain" (Int32,
/// the triangle markers). Connectivity and offsets are Int32 when they fit, Int64 otherwise.
/// \throws pdd::error naming the path for an inconsistent mesh or a failed write.
/// Complexity: linear; memory O(1) beyond the mesh. Thread-safety: reentrant.
inline void write_vtu(const std::filesystem::path& path, const triangle_mesh& mesh) {
  detail::check_mesh_for_writing(mesh, path);
  constexpr std::size_t i32max = static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max());
  const bool small = mesh.vertices.size() <= i32max && mesh.triangles.size() <= i32max / 3;
  write_file_atomically(path, [&](std::ostream& os) {
    if (small)
      detail::write_vtu_stream<std::int32_t>(os, mesh, "Int32");
    else
      detail::write_vtu_stream<std::int64_t>(os, mesh, "Int64");
  });
}

/// Writes a .pvtu index over .vtu pieces written by write_vtu (e.g. one per subdomain),
/// atomically. `piece_files` are written as given (paths relative to the .pvtu's directory,
/// XML-escaped); the PPointData/PCellData/PPoints declarations match write_vtu's arrays.
/// \throws pdd::error naming the path when writing fails or `piece_files` is empty.
/// Complexity: linear in the number of pieces. Thread-safety: reentrant.
inline void write_pvtu(const std::filesystem::path& path,
                       const std::vector<std::string>& piece_files) {
  if (piece_files.empty())
    throw error("cannot write '" + path.string() + "': a .pvtu needs at least one piece");
  write_file_atomically(path, [&](std::ostream& os) {
    os << "<?xml version=\"1.0\"?>\n"
       << "<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" byte_order=\""
       << detail::vtk_byte_order() << "\" header_type=\"UInt64\">\n"
       << "  <PUnstructuredGrid GhostLevel=\"0\">\n"
       << "    <PPointData Scalars=\"vertex_marker\">\n"
       << "      <PDataArray type=\"Int32\" Name=\"vertex_marker\"/>\n"
       << "    </PPointData>\n"
       << "    <PCellData Scalars=\"subdomain\">\n"
       << "      <PDataArray type=\"Int32\" Name=\"subdomain\"/>\n"
       << "    </PCellData>\n"
       << "    <PPoints>\n"
       << "      <PDataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"/>\n"
       << "    </PPoints>\n";
    for (const std::string& f : piece_files)
      os << "    <Piece Source=\"" << detail::xml_escape(f) << "\"/>\n";
    os << "  </PUnstructuredGrid>\n</VTKFile>\n";
  });
}

} // namespace pdd
