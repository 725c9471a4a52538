/// \file vtu.hpp
/// VTK XML UnstructuredGrid output (.vtu, read by ParaView, VisIt and meshio) and the
/// parallel index (.pvtu) over per-subdomain pieces.
#pragma once

#include <pdd/core/triangle_mesh.hpp>
#include <pdd/errors.hpp>
#include <pdd/io/atomic_file.hpp>
#include <pdd/io/detail/mesh.hpp>
#include <pdd/io/detail/vtu.hpp>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <ostream>
#include <span>
#include <string>
#include <vector>

namespace pdd {

/// Writes the mesh as a VTK XML UnstructuredGrid (.vtu), atomically, in binary appended raw
/// encoding (header_type UInt64, native byte order declared): 3D points (z = 0), triangle
/// cells (VTK type 5), point data "vertex_marker" (Int32) and cell data "subdomain" (Int32,
/// the triangle markers) and, when `region_attributes` is not empty, "region_attribute"
/// (Float64, one per triangle: pdd::region_attributes). Connectivity and offsets are Int32
/// when they fit, Int64 otherwise.
/// \throws pdd::error naming the path for an inconsistent mesh, region attributes that are
///   not one per triangle, or a failed write.
/// Complexity: linear; memory O(1) beyond the mesh. Thread-safety: reentrant.
inline void write_vtu(const std::filesystem::path& path, const triangle_mesh& mesh,
                      std::span<const double> region_attributes = {}) {
  detail::check_mesh_for_writing(mesh, path);
  detail::check_region_attributes(mesh, region_attributes, path);
  constexpr std::size_t i32max = static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max());
  const bool small = mesh.vertices.size() <= i32max && mesh.triangles.size() <= i32max / 3;
  write_file_atomically(path, [&](std::ostream& os) {
    if (small)
      detail::write_vtu_stream<std::int32_t>(os, mesh, "Int32", region_attributes);
    else
      detail::write_vtu_stream<std::int64_t>(os, mesh, "Int64", region_attributes);
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
