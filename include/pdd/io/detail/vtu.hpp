/// \file vtu.hpp
/// Implementation of pdd::write_vtu: the XML header and the appended raw data blocks of a VTK
/// XML UnstructuredGrid file.
#pragma once

#include <pdd/core/triangle_mesh.hpp>
#include <pdd/io/detail/mesh.hpp>
#include <pdd/io/detail/text.hpp>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <ostream>
#include <span>
#include <string>
#include <vector>

namespace pdd::detail {

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

/// Appends `<DataArray type= Name= [NumberOfComponents=] format="appended" offset=/>`.
inline void append_vtk_data_array(std::string& h, const char* type, const char* name, int comps,
                                  std::uint64_t offset) {
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
}

/// The byte offsets of a .vtu's appended arrays, in file order: the point data, the cell
/// data (the region attributes only when the file has them), the points and the cells.
struct vtu_offsets {
  std::uint64_t vertex_marker = 0, subdomain = 0, region_attribute = 0, points = 0,
                connectivity = 0, offsets = 0, types = 0;
  bool has_region_attribute = false;
};

/// The offsets for n points and t triangles with connectivity and offsets of index_bytes each;
/// every block has an 8-byte size header.
inline vtu_offsets vtu_layout(std::size_t n, std::size_t t, std::size_t index_bytes,
                              bool region_attribute) {
  vtu_offsets o;
  o.has_region_attribute = region_attribute;
  std::uint64_t acc = 0;
  const auto place = [&acc](std::uint64_t& at, std::size_t bytes) {
    at = acc;
    acc += 8 + bytes;
  };
  place(o.vertex_marker, n * 4);
  place(o.subdomain, t * 4);
  if (region_attribute) place(o.region_attribute, t * 8);
  place(o.points, n * 3 * 8);
  place(o.connectivity, t * 3 * index_bytes);
  place(o.offsets, t * index_bytes);
  place(o.types, t);
  return o;
}

/// The XML part of a .vtu up to the appended data's '_' marker: n points, t triangles, the
/// arrays at the offsets off with connectivity and offsets of index_type.
inline std::string vtu_header(std::size_t n, std::size_t t, const vtu_offsets& off,
                              const char* index_type) {
  std::string h;
  h += "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"";
  h += vtk_byte_order();
  h += "\" header_type=\"UInt64\">\n  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"";
  append_integer(h, n);
  h += "\" NumberOfCells=\"";
  append_integer(h, t);
  h += "\">\n";
  h += "      <PointData Scalars=\"vertex_marker\">\n";
  append_vtk_data_array(h, "Int32", "vertex_marker", 1, off.vertex_marker);
  h += "      </PointData>\n      <CellData Scalars=\"subdomain\">\n";
  append_vtk_data_array(h, "Int32", "subdomain", 1, off.subdomain);
  if (off.has_region_attribute)
    append_vtk_data_array(h, "Float64", "region_attribute", 1, off.region_attribute);
  h += "      </CellData>\n      <Points>\n";
  append_vtk_data_array(h, "Float64", "Points", 3, off.points);
  h += "      </Points>\n      <Cells>\n";
  append_vtk_data_array(h, index_type, "connectivity", 1, off.connectivity);
  append_vtk_data_array(h, index_type, "offsets", 1, off.offsets);
  append_vtk_data_array(h, "UInt8", "types", 1, off.types);
  h += "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n"
       "  <AppendedData encoding=\"raw\">\n   _";
  return h;
}

/// The .vtu file of the mesh (see pdd::write_vtu), connectivity and offsets of type Index,
/// the cell data "region_attribute" when `attributes` is not empty (one per triangle).
template <class Index>
void write_vtu_stream(std::ostream& os, const triangle_mesh& mesh, const char* index_type,
                      std::span<const double> attributes) {
  const std::size_t n = mesh.vertices.size();
  const std::size_t t = mesh.triangles.size();
  const vtu_offsets off = vtu_layout(n, t, sizeof(Index), !attributes.empty());
  const std::string h = vtu_header(n, t, off, index_type);
  os.write(h.data(), static_cast<std::streamsize>(h.size()));
  write_vtk_block<std::int32_t>(os, n, [&](std::size_t i) { return vertex_marker(mesh, i); });
  write_vtk_block<std::int32_t>(os, t, [&](std::size_t i) { return triangle_marker(mesh, i); });
  if (!attributes.empty())
    write_vtk_block<double>(os, t, [&](std::size_t i) { return attributes[i]; });
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

} // namespace pdd::detail
