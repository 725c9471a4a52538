/// \file piece_files.hpp
/// The two formats of a per-subdomain mesh (one file per subdomain and an index over them):
/// VTK XML (.vtu pieces, a .pvtu index) and pdd's binary format (.pddm pieces, a .pddi index;
/// docs/binary-mesh-format.md). Their file names, writers, readers that tell the format from
/// the file, and the estimated bytes on disk.
#pragma once

#include <pdd/core/triangle_mesh.hpp>
#include <pdd/errors.hpp>
#include <pdd/io/binary_mesh.hpp>
#include <pdd/io/vtu.hpp>
#include <pdd/io/vtu_read.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace pdd {

/// The file format of a per-subdomain mesh.
enum class piece_format {
  vtu,   ///< subdomain_<id>.vtu pieces (pdd::write_vtu), index mesh.pvtu
  binary ///< subdomain_<id>.pddm pieces (pdd::write_binary_mesh), index mesh.pddi
};

/// "vtu" or "binary".
inline const char* to_string(piece_format f) noexcept {
  return f == piece_format::binary ? "binary" : "vtu";
}

/// The extension of a piece file, with its dot.
inline const char* piece_extension(piece_format f) noexcept {
  return f == piece_format::binary ? ".pddm" : ".vtu";
}

/// The file name of subdomain id's piece: subdomain_<id>.vtu or subdomain_<id>.pddm.
inline std::string piece_file_name(index_t id, piece_format f = piece_format::vtu) {
  return "subdomain_" + std::to_string(id) + piece_extension(f);
}

/// The default index file name: mesh.pvtu or mesh.pddi.
inline const char* piece_index_name(piece_format f) noexcept {
  return f == piece_format::binary ? "mesh.pddi" : "mesh.pvtu";
}

/// Writes one piece in format f (write_vtu or write_binary_mesh), atomically.
inline void write_piece(const std::filesystem::path& path, const triangle_mesh& mesh,
                        piece_format f) {
  if (f == piece_format::binary)
    write_binary_mesh(path, mesh);
  else
    write_vtu(path, mesh);
}

/// Writes the index over `piece_files` in format f (write_pvtu or write_binary_mesh_index).
inline void write_piece_index(const std::filesystem::path& path,
                              const std::vector<std::string>& piece_files, piece_format f) {
  if (f == piece_format::binary)
    write_binary_mesh_index(path, piece_files);
  else
    write_pvtu(path, piece_files);
}

/// The format of the piece or index file at `path`, from its first bytes (the binary magic, the
/// "pdd-mesh-index" line, or XML). \throws pdd::error "path: ..." when it cannot be read or is
/// neither.
inline piece_format detect_piece_format(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw error(path.string() + ": cannot open for reading");
  std::string start(16, '\0');
  in.read(start.data(), static_cast<std::streamsize>(start.size()));
  start.resize(static_cast<std::size_t>(in.gcount()));
  const std::string magic(detail::binary_mesh_magic.data(), detail::binary_mesh_magic.size());
  if (start.rfind(magic, 0) == 0 || start.rfind(binary_mesh_index_tag, 0) == 0)
    return piece_format::binary;
  if (start.rfind("<?xml", 0) == 0 || start.rfind("<VTKFile", 0) == 0) return piece_format::vtu;
  throw error(path.string() + ": neither a pdd binary mesh file nor a VTK XML file");
}

/// Reads one piece, VTU or binary (told from its first bytes; read_vtu or read_binary_mesh).
/// \throws as those, naming the file.
inline triangle_mesh read_piece(const std::filesystem::path& path) {
  return detect_piece_format(path) == piece_format::binary ? read_binary_mesh(path)
                                                           : read_vtu(path);
}

/// Reads an index, .pvtu or .pddi (told from its first bytes): its pieces' paths.
/// \throws as read_pvtu or read_binary_mesh_index, naming the file.
inline std::vector<std::filesystem::path> read_piece_index(const std::filesystem::path& path) {
  return detect_piece_format(path) == piece_format::binary ? read_binary_mesh_index(path)
                                                           : read_pvtu(path);
}

/// Estimated bytes on disk of a per-subdomain mesh of `triangles` triangles in `pieces` pieces
/// in format f, as the writers store them: a piece has about half as many vertices as
/// triangles (plus its boundary: 64 more per piece here, a margin), and a fixed part (the VTU's
/// XML, the binary header and marker runs), plus the index. VTU: 21 bytes per triangle
/// (connectivity, offset, type, marker) and 28 per vertex (3 float64, marker): about 35 per
/// triangle. Binary: 16 per vertex (2 float64) and 3 x bit_width(vertices per piece) bits per
/// triangle: about 13.6 per triangle for pieces of 60K triangles. Complexity O(1).
inline double estimated_piece_bytes(piece_format f, double triangles, double pieces) {
  pieces = std::max(1.0, pieces);
  const double vertices = 0.5 * triangles + 64.0 * pieces;
  if (f == piece_format::binary) {
    const double per_piece = std::min(vertices / pieces, 4.0e9);
    const double index_bits = detail::binary_index_bits(static_cast<std::uint64_t>(per_piece));
    return 3.0 * index_bits / 8.0 * triangles + 16.0 * vertices + 128.0 * pieces + 1024.0;
  }
  return 21.0 * triangles + 28.0 * vertices + 1400.0 * pieces + 1024.0;
}

} // namespace pdd
