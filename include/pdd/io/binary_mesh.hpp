/// \file binary_mesh.hpp
/// pdd's compact binary mesh piece (.pddm, docs/binary-mesh-format.md): float64 coordinates
/// kept bitwise, run-length markers and bit-packed connectivity (about 14 bytes per triangle
/// against VTU's 35), a version and an FNV-1a checksum; and its text index (.pddi) over the
/// pieces of a per-subdomain mesh, as a .pvtu is over .vtu pieces.
#pragma once

#include <pdd/core/triangle_mesh.hpp>
#include <pdd/errors.hpp>
#include <pdd/io/atomic_file.hpp>
#include <pdd/io/detail/binary_mesh.hpp>
#include <pdd/io/detail/mesh.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace pdd {

/// The binary mesh version this library writes, and the only one it reads.
inline constexpr std::uint32_t binary_mesh_version = 1;

/// The first line of a .pddi index (followed by its version).
inline constexpr const char* binary_mesh_index_tag = "pdd-mesh-index";

/// Writes the mesh as a binary piece (docs/binary-mesh-format.md), atomically: vertices
/// (float64 bits, little-endian), vertex markers, triangle markers and triangles, in the
/// mesh's own order (segments are not stored). The piece is encoded in memory first (about
/// 14 bytes per triangle) to compute its checksum.
/// \throws pdd::error naming the path for an inconsistent mesh or a failed write.
/// Complexity: linear. Thread-safety: reentrant.
inline void write_binary_mesh(const std::filesystem::path& path, const triangle_mesh& mesh) {
  detail::check_mesh_for_writing(mesh, path);
  std::uint64_t sizes[3];
  const std::string body = detail::encode_binary_sections(mesh, sizes);
  std::string head(detail::binary_mesh_magic.data(), detail::binary_mesh_magic.size());
  detail::put_le(head, binary_mesh_version, 4);
  detail::put_le(head, 0, 4); // flags
  detail::put_le(head, mesh.vertices.size(), 8);
  detail::put_le(head, mesh.triangles.size(), 8);
  for (const std::uint64_t s : sizes)
    detail::put_le(head, s, 8);
  detail::put_le(head, detail::fnv1a64(body, detail::fnv1a64(head)), 8);
  write_file_atomically(path, [&](std::ostream& os) {
    os.write(head.data(), static_cast<std::streamsize>(head.size()));
    os.write(body.data(), static_cast<std::streamsize>(body.size()));
  });
}

namespace detail {

/// The sizes a binary piece's header announces.
struct binary_mesh_header_info {
  std::uint64_t vertices = 0, triangles = 0, sections[3] = {0, 0, 0}, checksum = 0;
};

/// Checks the header `head` (64 bytes) of a file of `file_size` bytes: magic, version, flags,
/// counts and section sizes consistent with each other and with the file size.
inline binary_mesh_header_info check_binary_mesh_header(const std::filesystem::path& path,
                                                        const char* head, std::uint64_t file_size) {
  if (!std::equal(binary_mesh_magic.begin(), binary_mesh_magic.end(), head))
    throw binary_mesh_error(path, "not a pdd binary mesh (wrong magic bytes)");
  const std::uint64_t version = get_le(head + 8, 4);
  if (version != binary_mesh_version)
    throw binary_mesh_error(path, "binary mesh version " + std::to_string(version) +
                                      "; this reader reads version " +
                                      std::to_string(binary_mesh_version) + " only");
  if (get_le(head + 12, 4) != 0) throw binary_mesh_error(path, "unknown flags in the header");
  binary_mesh_header_info h;
  h.vertices = get_le(head + 16, 8);
  h.triangles = get_le(head + 24, 8);
  for (int k = 0; k < 3; ++k)
    h.sections[k] = get_le(head + 32 + 8 * k, 8);
  h.checksum = get_le(head + 56, 8);
  // bounds that also keep the sums below from overflowing
  if (h.vertices > file_size / 16 || h.triangles > file_size / 3 * 8 || h.vertices > no_index ||
      h.triangles > no_index || h.sections[0] > file_size || h.sections[1] > file_size ||
      h.sections[2] != binary_connectivity_bytes(h.vertices, h.triangles))
    throw binary_mesh_error(path, "the header's counts do not fit the file's " +
                                      std::to_string(file_size) + " bytes (truncated or tampered)");
  const std::uint64_t expected =
      binary_mesh_header_bytes + 16 * h.vertices + h.sections[0] + h.sections[1] + h.sections[2];
  if (expected != file_size)
    throw binary_mesh_error(path, "the file has " + std::to_string(file_size) +
                                      " bytes, its header announces " + std::to_string(expected) +
                                      (file_size < expected ? " (truncated)" : " (tampered)"));
  return h;
}

} // namespace detail

/// Reads a binary piece written by pdd::write_binary_mesh: vertices, triangles, vertex_markers
/// and triangle_markers (segments stay empty), bitwise as written.
/// \throws pdd::error "path: what is wrong" for a file that cannot be opened, is not a pdd
/// binary mesh (magic), has another version or unknown flags, is truncated or longer than its
/// header announces, fails its checksum (changed after it was written), or holds a bad varint,
/// a marker outside 32 bits, a missing vertex index or a non-finite coordinate. Never reads past
/// the end of the file. Complexity: linear; memory: the file and the mesh. Thread-safety:
/// reentrant.
inline triangle_mesh read_binary_mesh(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw detail::binary_mesh_error(path, "cannot open for reading");
  in.seekg(0, std::ios::end);
  const auto file_size = static_cast<std::uint64_t>(in.tellg());
  in.seekg(0);
  if (file_size < detail::binary_mesh_header_bytes)
    throw detail::binary_mesh_error(path,
                                    "only " + std::to_string(file_size) +
                                        " bytes: too short for a pdd binary mesh (truncated?)");
  std::string bytes(static_cast<std::size_t>(file_size), '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(file_size));
  if (!in) throw detail::binary_mesh_error(path, "cannot read the file");
  const auto h = detail::check_binary_mesh_header(path, bytes.data(), file_size);
  const std::string_view all(bytes), body = all.substr(detail::binary_mesh_header_bytes);
  if (detail::fnv1a64(body, detail::fnv1a64(all.substr(0, 56))) != h.checksum)
    throw detail::binary_mesh_error(
        path, "checksum mismatch: the file was changed or damaged after it was written");
  triangle_mesh m;
  detail::decode_binary_coordinates(body, path, static_cast<std::size_t>(h.vertices), m);
  std::string_view rest = body.substr(16 * m.vertices.size());
  detail::decode_marker_runs({rest.substr(0, h.sections[0]), path, "vertex marker"},
                             m.vertices.size(), m.vertex_markers);
  rest.remove_prefix(h.sections[0]);
  m.triangles.resize(static_cast<std::size_t>(h.triangles));
  detail::decode_marker_runs({rest.substr(0, h.sections[1]), path, "triangle marker"},
                             m.triangles.size(), m.triangle_markers);
  rest.remove_prefix(h.sections[1]);
  detail::decode_binary_triangles(rest, path, m.vertices.size(), m);
  return m;
}

/// Writes a .pddi index over binary pieces, atomically: the line "pdd-mesh-index 1", the line
/// "pieces N", then one piece file name per line (relative to the index's folder).
/// \throws pdd::error naming the path when `piece_files` is empty, a name is empty, absolute or
/// holds a line break, or writing fails. Complexity: linear. Thread-safety: reentrant.
inline void write_binary_mesh_index(const std::filesystem::path& path,
                                    const std::vector<std::string>& piece_files) {
  const std::string where = "cannot write '" + path.string() + "': ";
  if (piece_files.empty()) throw error(where + "an index needs at least one piece");
  for (const std::string& f : piece_files)
    if (f.empty() || f.find_first_of("\r\n") != std::string::npos ||
        std::filesystem::path(f).is_absolute())
      throw error(where + "bad piece file name '" + f + "'");
  write_file_atomically(path, [&](std::ostream& os) {
    os << binary_mesh_index_tag << ' ' << binary_mesh_version << "\npieces " << piece_files.size()
       << '\n';
    for (const std::string& f : piece_files)
      os << f << '\n';
  });
}

/// Reads a .pddi index written by pdd::write_binary_mesh_index: the paths of its pieces, in
/// file order, resolved against the index's folder.
/// \throws pdd::error "path:line: what is wrong" when the file cannot be read, does not start
/// with "pdd-mesh-index 1", lacks "pieces N" (N >= 1), lists another number of pieces, or has an
/// empty or absolute piece name. Complexity: linear. Thread-safety: reentrant.
inline std::vector<std::filesystem::path>
read_binary_mesh_index(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw detail::binary_mesh_error(path, "cannot open for reading");
  const auto fail = [&](std::size_t line, const std::string& what) {
    return error(path.string() + ":" + std::to_string(line) + ": " + what);
  };
  std::string line;
  const std::string tag = std::string(binary_mesh_index_tag) + " ";
  if (!std::getline(in, line) || line.rfind(tag, 0) != 0)
    throw fail(1, "not a pdd mesh index (expected '" + tag + "1')");
  if (line != tag + std::to_string(binary_mesh_version))
    throw fail(1, "index version '" + line.substr(tag.size()) + "'; this reader reads version " +
                      std::to_string(binary_mesh_version) + " only");
  std::size_t count = 0;
  if (!std::getline(in, line) || line.rfind("pieces ", 0) != 0 || line.size() > 7 + 9 ||
      line.find_first_not_of("0123456789", 7) != std::string::npos || line.size() == 7 ||
      (count = std::stoull(line.substr(7))) == 0)
    throw fail(2, "expected 'pieces N' with N >= 1");
  std::vector<std::filesystem::path> pieces;
  for (std::size_t k = 0; k < count; ++k) {
    if (!std::getline(in, line))
      throw fail(3 + k, "the index announces " + std::to_string(count) + " pieces and lists " +
                            std::to_string(k) + " (truncated?)");
    if (line.empty() || std::filesystem::path(line).is_absolute())
      throw fail(3 + k, "empty or absolute piece file name");
    pieces.push_back(path.parent_path() / line);
  }
  if (std::getline(in, line)) throw fail(3 + count, "more lines than the pieces it announces");
  return pieces;
}

} // namespace pdd
