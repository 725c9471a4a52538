/// \file piece_manifest.hpp
/// The manifest of a per-subdomain output (issue 40): the fingerprint of the run that writes
/// the directory and, for each finished piece, its file name, size and checksum (CRC-64/XZ,
/// Boost.CRC), so that a resumed run keeps the pieces that are complete and intact and meshes
/// only the others. The data, the checksum, the checks and the comparison of fingerprints; the
/// manifest's file format (JSON) is the programs' (no pdd header uses JSON), see
/// docs/reference/pdd-mesh.md.
#pragma once

#include <pdd/core/index.hpp>
#include <pdd/errors.hpp>
#include <pdd/io/piece_files.hpp>

#include <boost/crc.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <system_error>
#include <vector>

namespace pdd {

/// What determines a run's output, item by item: "--max-area" -> "0.001", "input" -> its
/// checksum and size, "pdd version", the plan's N and path. Two runs with equal fingerprints
/// write the same bytes (pdd is bitwise deterministic for a given N).
using run_fingerprint = std::map<std::string, std::string>;

/// One finished piece of a per-subdomain output.
struct piece_record {
  std::string file;           ///< its file name in the directory (piece_file_name)
  std::uintmax_t size = 0;    ///< bytes
  std::uint64_t checksum = 0; ///< CRC-64/XZ of its bytes (piece_checksum)
  /// \var triangles
  /// The number of triangles of the piece's mesh.
  /// \var vertices
  /// The number of vertices of the piece's mesh (its interface vertices counted too).
  std::size_t triangles = 0, vertices = 0;
  /// Memberwise equality (file, size, checksum and counts).
  friend bool operator==(const piece_record&, const piece_record&) = default;
};

/// A per-subdomain output's manifest: the run's fingerprint and its finished pieces by id.
struct piece_manifest {
  /// The fingerprint of the run that wrote the pieces: a resumed run keeps them only when its
  /// own is equal (pdd::fingerprint_differences).
  run_fingerprint fingerprint;
  /// The finished pieces, by subdomain id (ascending); empty: none finished yet.
  std::map<index_t, piece_record> pieces;
};

/// The manifest's file name in the output directory.
inline constexpr const char* piece_manifest_name = "pdd-manifest.json";

/// The name of the checksum piece_record::checksum holds (written into the manifest).
inline constexpr const char* piece_checksum_name = "crc64-xz";

/// CRC-64/XZ (ECMA-182 polynomial, reflected, all-ones initial value and final xor), the
/// checksum of xz; Boost.CRC's table-driven implementation.
using crc64_xz = boost::crc_optimal<64, 0x42F0E1EBA9EA3693ULL, 0xFFFFFFFFFFFFFFFFULL,
                                    0xFFFFFFFFFFFFFFFFULL, true, true>;

/// The size and CRC-64/XZ of the file at `path`. \throws pdd::error naming the file when it
/// cannot be read. Complexity: linear in its bytes.
inline piece_record piece_checksum(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw error("cannot read '" + path.string() + "'");
  crc64_xz crc;
  std::array<char, 1 << 16> buffer{};
  piece_record r;
  r.file = path.filename().string();
  while (in) {
    in.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    const auto n = static_cast<std::size_t>(in.gcount());
    crc.process_bytes(buffer.data(), n);
    r.size += n;
  }
  if (in.bad()) throw error("cannot read '" + path.string() + "'");
  r.checksum = crc.checksum();
  return r;
}

/// "input" -> "<checksum hex> <size> bytes" of the file at `path` (piece_checksum), the
/// fingerprint item of an input file. \throws as piece_checksum.
inline std::string file_fingerprint(const std::filesystem::path& path) {
  const piece_record r = piece_checksum(path);
  char text[64];
  std::snprintf(text, sizeof text, "%016llx %ju bytes", static_cast<unsigned long long>(r.checksum),
                r.size);
  return text;
}

/// True when `record`'s file exists in `dir` with its size and checksum (a truncated, extended
/// or changed piece is not intact; the size is compared first, without reading the file).
inline bool piece_intact(const std::filesystem::path& dir, const piece_record& record) {
  std::error_code ec;
  const std::filesystem::path p = dir / record.file;
  const std::uintmax_t size = std::filesystem::file_size(p, ec);
  if (ec || size != record.size) return false;
  try {
    const piece_record now = piece_checksum(p);
    return now.size == record.size && now.checksum == record.checksum;
  } catch (const error&) {
    return false;
  }
}

/// The pieces of `m` a resumed run of `n` subdomains in format f keeps: ids below n, named as
/// piece_file_name names them, and intact in `dir` (piece_intact). Complexity: reads every
/// listed piece once.
inline std::map<index_t, piece_record> intact_pieces(const piece_manifest& m,
                                                     const std::filesystem::path& dir,
                                                     std::size_t n, piece_format f) {
  std::map<index_t, piece_record> out;
  for (const auto& [id, record] : m.pieces)
    if (id < n && record.file == piece_file_name(id, f) && piece_intact(dir, record))
      out.emplace(id, record);
  return out;
}

/// The items in which `now` differs from `then` (a manifest's), one phrase each: "option
/// --max-area differs: 0.001 in the manifest, 0.002 now" (items whose name starts with "--"
/// are options), "input differs: ... in the manifest, ... now", "... is missing". Empty when
/// they are equal.
inline std::vector<std::string> fingerprint_differences(const run_fingerprint& then,
                                                        const run_fingerprint& now) {
  std::vector<std::string> out;
  const auto what = [](const std::string& key) {
    return (key.rfind("--", 0) == 0 ? "option " : "") + key;
  };
  for (const auto& [key, value] : now) {
    const auto it = then.find(key);
    if (it == then.end())
      out.push_back(what(key) + " is not in the manifest (now " + value + ")");
    else if (it->second != value)
      out.push_back(what(key) + " differs: " + it->second + " in the manifest, " + value + " now");
  }
  for (const auto& [key, value] : then)
    if (!now.contains(key)) out.push_back(what(key) + " is in the manifest only (" + value + ")");
  return out;
}

/// True for a file name pdd's per-subdomain output writes in its directory: a piece
/// (subdomain_<id>.vtu or .pddm), an index (mesh.pvtu, mesh.pddi), the manifest, or the
/// temporary of one of them (".<name>.pdd-tmp-<digits>", left by a killed run).
inline bool is_piece_output_name(std::string name) {
  if (name.size() > 1 && name[0] == '.') {
    const std::size_t tmp = name.rfind(".pdd-tmp-");
    if (tmp == std::string::npos) return false;
    name = name.substr(1, tmp - 1);
  }
  if (name == "mesh.pvtu" || name == "mesh.pddi" || name == piece_manifest_name) return true;
  if (name.rfind("subdomain_", 0) != 0) return false;
  const std::size_t dot = name.find('.');
  const std::string ext = dot == std::string::npos ? "" : name.substr(dot);
  const std::string digits = name.substr(10, dot - 10);
  return (ext == ".vtu" || ext == ".pddm") && !digits.empty() &&
         digits.find_first_not_of("0123456789") == std::string::npos;
}

/// Removes from `dir` the files is_piece_output_name names, those of `keep` excepted
/// (--overwrite: everything; a resumed run: the temporaries and the pieces it does not keep).
/// Other files stay. \throws pdd::error naming a file that cannot be removed.
inline void remove_piece_outputs(const std::filesystem::path& dir,
                                 const std::vector<std::string>& keep = {}) {
  std::error_code ec;
  std::vector<std::filesystem::path> doomed;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (is_piece_output_name(name) && std::find(keep.begin(), keep.end(), name) == keep.end())
      doomed.push_back(e.path());
  }
  for (const auto& p : doomed)
    if (!std::filesystem::remove(p, ec) && ec)
      throw error("cannot remove '" + p.string() + "': " + ec.message());
}

} // namespace pdd
