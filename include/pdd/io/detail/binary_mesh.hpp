/// \file binary_mesh.hpp
/// Implementation of pdd's binary mesh piece (docs/binary-mesh-format.md): little-endian
/// fixed-width fields, LEB128 varints with zigzag signs, the FNV-1a 64 checksum, and the
/// encoding and the checked decoding of the four sections.
#pragma once

#include <pdd/core/triangle_mesh.hpp>
#include <pdd/errors.hpp>
#include <pdd/io/detail/mesh.hpp>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace pdd::detail {

/// The 8 bytes every binary piece starts with.
inline constexpr std::array<char, 8> binary_mesh_magic{'P', 'D', 'D', 'M', 'E', 'S', 'H', '\x1a'};
/// Bytes of the fixed header (magic, version, flags, six 64-bit fields).
inline constexpr std::size_t binary_mesh_header_bytes = 64;

/// The error for file `path`: "path: what".
inline error binary_mesh_error(const std::filesystem::path& path, const std::string& what) {
  return error(path.string() + ": " + what);
}

/// Appends v as `bytes` little-endian bytes.
inline void put_le(std::string& out, std::uint64_t v, int bytes) {
  for (int i = 0; i < bytes; ++i, v >>= 8)
    out += static_cast<char>(v & 0xff);
}

/// The little-endian unsigned value of `bytes` bytes at p.
inline std::uint64_t get_le(const char* p, int bytes) noexcept {
  std::uint64_t v = 0;
  for (int i = bytes - 1; i >= 0; --i)
    v = (v << 8) | static_cast<unsigned char>(p[i]);
  return v;
}

/// Appends v as an unsigned LEB128 varint (7 bits per byte, low first, high bit: more follow).
inline void put_varint(std::string& out, std::uint64_t v) {
  while (v >= 0x80) {
    out += static_cast<char>((v & 0x7f) | 0x80);
    v >>= 7;
  }
  out += static_cast<char>(v);
}

inline std::uint64_t zigzag(std::int64_t v) noexcept {
  return (static_cast<std::uint64_t>(v) << 1) ^ static_cast<std::uint64_t>(v >> 63);
}
inline std::int64_t unzigzag(std::uint64_t u) noexcept {
  return static_cast<std::int64_t>(u >> 1) ^ -static_cast<std::int64_t>(u & 1);
}

inline constexpr std::uint64_t fnv1a64_offset_basis = 0xcbf29ce484222325ULL;

/// FNV-1a, 64 bits, over `bytes`, continuing from h (the offset basis for a fresh hash).
inline std::uint64_t fnv1a64(std::string_view bytes,
                             std::uint64_t h = fnv1a64_offset_basis) noexcept {
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ULL;
  }
  return h;
}

/// Appends the runs of equal values of marker(i), i < count: (run length, zigzag marker)
/// varint pairs.
template <class Marker>
void put_marker_runs(std::string& out, std::size_t count, const Marker& marker) {
  for (std::size_t i = 0; i < count;) {
    std::size_t run = 1;
    while (i + run < count && marker(i + run) == marker(i))
      ++run;
    put_varint(out, run);
    put_varint(out, zigzag(marker(i)));
    i += run;
  }
}

/// Bits per vertex index in a piece of n vertices: bit_width(n - 1), at least 1.
inline int binary_index_bits(std::uint64_t n) noexcept {
  return n <= 2 ? 1 : static_cast<int>(std::bit_width(n - 1));
}

/// Bytes of the connectivity section: 3 t indices of binary_index_bits(n) bits, rounded up.
inline std::uint64_t binary_connectivity_bytes(std::uint64_t n, std::uint64_t t) noexcept {
  return (3 * t * static_cast<std::uint64_t>(binary_index_bits(n)) + 7) / 8;
}

/// The sections of a piece after the header: coordinates, vertex marker runs, triangle marker
/// runs, bit-packed connectivity; `sizes` receives the byte size of the last three.
inline std::string encode_binary_sections(const triangle_mesh& m, std::uint64_t (&sizes)[3]) {
  const std::size_t n = m.vertices.size(), t = m.triangles.size();
  std::string out;
  out.reserve(16 * n + 6 * t + 64);
  for (const point& p : m.vertices) {
    put_le(out, std::bit_cast<std::uint64_t>(p.x), 8);
    put_le(out, std::bit_cast<std::uint64_t>(p.y), 8);
  }
  std::size_t mark = out.size();
  put_marker_runs(out, n, [&](std::size_t i) { return vertex_marker(m, i); });
  sizes[0] = out.size() - mark;
  mark = out.size();
  put_marker_runs(out, t, [&](std::size_t i) { return triangle_marker(m, i); });
  sizes[1] = out.size() - mark;
  mark = out.size();
  const int w = binary_index_bits(n);
  std::uint64_t acc = 0; // bits not yet written, lowest first
  int bits = 0;
  for (const auto& tri : m.triangles)
    for (const index_t v : tri) {
      acc |= static_cast<std::uint64_t>(v) << bits;
      for (bits += w; bits >= 8; bits -= 8, acc >>= 8)
        out += static_cast<char>(acc & 0xff);
    }
  if (bits > 0) out += static_cast<char>(acc & 0xff); // the last byte, padded with zero bits
  sizes[2] = out.size() - mark;
  return out;
}

/// Reads varints from one section of a file's bytes, refusing to leave it.
class varint_cursor {
public:
  varint_cursor(std::string_view section, const std::filesystem::path& path, const char* name)
      : s_(section), path_(path), name_(name) {}

  /// The next varint. \throws pdd::error naming the file and section when it runs past the
  /// section's end or is longer than 10 bytes (more than 64 bits).
  std::uint64_t next() {
    std::uint64_t v = 0;
    for (int shift = 0; shift < 64; shift += 7) {
      if (at_ == s_.size()) fail("ends inside a number (truncated or tampered)");
      const auto byte = static_cast<unsigned char>(s_[at_++]);
      if (shift == 63 && byte > 1) fail("holds a number wider than 64 bits");
      v |= static_cast<std::uint64_t>(byte & 0x7f) << shift;
      if (!(byte & 0x80)) return v;
    }
    fail("holds a number wider than 64 bits");
  }
  /// The next varint as a zigzag-coded int32 marker.
  std::int32_t next_marker() {
    const std::int64_t v = unzigzag(next());
    if (v < std::numeric_limits<std::int32_t>::min() ||
        v > std::numeric_limits<std::int32_t>::max())
      fail("holds a marker outside the 32-bit range");
    return static_cast<std::int32_t>(v);
  }
  /// \throws pdd::error unless every byte of the section was read.
  void expect_end() const {
    if (at_ != s_.size()) fail("has bytes left over after its last value (tampered)");
  }
  [[noreturn]] void fail(const std::string& what) const {
    throw binary_mesh_error(path_, std::string("the ") + name_ + " section " + what);
  }

private:
  std::string_view s_;
  std::size_t at_ = 0;
  const std::filesystem::path& path_;
  const char* name_;
};

/// Decodes the n vertices from the coordinates section at the start of `body` (its size checked
/// against the header already) into m.vertices; every coordinate must be finite.
inline void decode_binary_coordinates(std::string_view body, const std::filesystem::path& path,
                                      std::size_t n, triangle_mesh& m) {
  m.vertices.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double x = std::bit_cast<double>(get_le(body.data() + 16 * i, 8));
    const double y = std::bit_cast<double>(get_le(body.data() + 16 * i + 8, 8));
    if (!std::isfinite(x) || !std::isfinite(y))
      throw binary_mesh_error(path, "vertex " + std::to_string(i) + " has a non-finite coordinate");
    m.vertices[i] = {x, y};
  }
}

/// Decodes the bit-packed connectivity section `section` (its size checked against the header
/// already) into m.triangles: every index checked against n, the padding bits must be zero.
inline void decode_binary_triangles(std::string_view section, const std::filesystem::path& path,
                                    std::size_t n, triangle_mesh& m) {
  const int w = binary_index_bits(n);
  const std::uint64_t mask = (std::uint64_t{1} << w) - 1;
  std::uint64_t acc = 0;
  int bits = 0;
  std::size_t at = 0;
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      for (; bits < w; bits += 8)
        acc |= static_cast<std::uint64_t>(static_cast<unsigned char>(section[at++])) << bits;
      const std::uint64_t v = acc & mask;
      acc >>= w;
      bits -= w;
      if (v >= n)
        throw binary_mesh_error(path, "triangle " + std::to_string(t) +
                                          " refers to missing vertex " + std::to_string(v));
      m.triangles[t][static_cast<std::size_t>(k)] = static_cast<index_t>(v);
    }
  if (acc != 0 || at != section.size())
    throw binary_mesh_error(path, "the connectivity section's padding is not zero (tampered)");
}

/// Decodes a marker run section into `markers` (`count` values: the runs must sum to it).
inline void decode_marker_runs(varint_cursor in, std::size_t count,
                               std::vector<std::int32_t>& markers) {
  markers.clear();
  markers.reserve(count);
  while (markers.size() < count) {
    const std::uint64_t run = in.next();
    const std::int32_t marker = in.next_marker();
    if (run == 0 || run > count - markers.size())
      in.fail("has a run of " + std::to_string(run) + " that does not fit its count " +
              std::to_string(count));
    markers.insert(markers.end(), static_cast<std::size_t>(run), marker);
  }
  in.expect_end();
}

} // namespace pdd::detail
