// pdd's binary mesh piece (.pddm) and index (.pddi): round trips bitwise (odd doubles, markers
// of both signs, every index width up to 17 bits), the layout of docs/binary-mesh-format.md,
// and clean refusals naming the file for truncated, extended, tampered, wrong-magic and
// wrong-version files; the format-neutral readers (pdd::read_piece, pdd::read_piece_index).
#include <pdd/io/binary_mesh.hpp>
#include <pdd/io/piece_files.hpp>
#include <pdd/io/vtu.hpp>

#include "mesh_compare.hpp"
#include "random_soup.hpp"
#include "test_files.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace binary_mesh_test {
namespace fs = std::filesystem;

namespace {

using pdd::test::random_triangle_soup;

/// Expects the mesh read back to hold the written one's bytes (segments aside: the piece
/// formats do not store them).
void expect_bitwise_equal(const pdd::triangle_mesh& read, pdd::triangle_mesh written) {
  written.segments.clear();
  EXPECT_TRUE(pdd::test::bitwise_equal(read, written));
}

std::string error_of(const fs::path& p) {
  try {
    (void)pdd::read_binary_mesh(p);
  } catch (const pdd::error& e) {
    return e.what();
  }
  return "";
}

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void write_bytes(const fs::path& p, const std::string& bytes) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

/// Expects read_binary_mesh to refuse the file with a message naming it and holding `what`.
void expect_refused(const fs::path& p, const std::string& what) {
  const std::string e = error_of(p);
  EXPECT_EQ(e.rfind(p.string() + ": ", 0), 0u) << e;
  EXPECT_NE(e.find(what), std::string::npos) << e;
}

} // namespace

TEST(BinaryMesh, RoundTripIsBitwise) {
  std::size_t checked = 0;
  for (const std::size_t nv : {1u, 2u, 3u, 5u, 130u, 1000u, 70000u}) {
    const auto m = random_triangle_soup(static_cast<unsigned>(nv), nv, nv * 2 + 1);
    const auto p = pdd::test::temp_path("rt_" + std::to_string(nv) + ".pddm");
    pdd::write_binary_mesh(p, m);
    expect_bitwise_equal(pdd::read_binary_mesh(p), m);
    ++checked;
  }
  // odd doubles: signed zero, subnormals, extremes
  pdd::triangle_mesh odd = random_triangle_soup(7, 6, 4);
  odd.vertices[0] = {-0.0, std::numeric_limits<double>::denorm_min()};
  odd.vertices[1] = {std::numeric_limits<double>::max(), -std::numeric_limits<double>::min()};
  odd.vertex_markers[2] = std::numeric_limits<int>::min();
  odd.triangle_markers[3] = std::numeric_limits<int>::max();
  const auto p = pdd::test::temp_path("odd.pddm");
  pdd::write_binary_mesh(p, odd);
  expect_bitwise_equal(pdd::read_binary_mesh(p), odd);
  // no markers: read back as zeros; an empty mesh
  pdd::triangle_mesh bare = random_triangle_soup(9, 10, 12);
  bare.vertex_markers.clear();
  bare.triangle_markers.clear();
  pdd::write_binary_mesh(p, bare);
  const auto back = pdd::read_binary_mesh(p);
  EXPECT_EQ(back.vertex_markers, std::vector<int>(10, 0));
  EXPECT_EQ(back.triangle_markers, std::vector<int>(12, 0));
  pdd::write_binary_mesh(p, pdd::triangle_mesh{});
  EXPECT_TRUE(pdd::read_binary_mesh(p).triangles.empty());
  EXPECT_EQ(checked, 7u);
}

// The layout of docs/binary-mesh-format.md on the hand-made mesh: 8 vertices (3-bit indices),
// 8 triangles.
TEST(BinaryMesh, LayoutIsTheDocumentedOne) {
  const auto m = pdd::test::small_mesh();
  const auto p = pdd::test::temp_path("small.pddm");
  pdd::write_binary_mesh(p, m);
  const std::string b = read_bytes(p);
  EXPECT_EQ(b.substr(0, 8), std::string("PDDMESH\x1a", 8));
  const auto le = [&](std::size_t at, int n) {
    std::uint64_t v = 0;
    for (int i = n - 1; i >= 0; --i)
      v = (v << 8) | static_cast<unsigned char>(b[at + static_cast<std::size_t>(i)]);
    return v;
  };
  EXPECT_EQ(le(8, 4), 1u);  // version
  EXPECT_EQ(le(12, 4), 0u); // flags
  EXPECT_EQ(le(16, 8), 8u);
  EXPECT_EQ(le(24, 8), 8u);
  // vertex markers 1 1 2 2 3 4 0 0: runs (2,1) (2,2) (1,3) (1,4) (2,0), zigzag doubles them
  EXPECT_EQ(le(32, 8), 10u);
  EXPECT_EQ(b.substr(64 + 128, 10), std::string("\x02\x02\x02\x04\x01\x06\x01\x08\x02\x00", 10));
  EXPECT_EQ(le(40, 8), 4u);                   // triangle markers: (4, 0) (4, 1)
  EXPECT_EQ(le(48, 8), (3u * 8 * 3 + 7) / 8); // 24 indices of 3 bits
  EXPECT_EQ(b.size(), 64 + 128 + 10 + 4 + 9u);
  EXPECT_EQ(std::bit_cast<double>(le(64 + 16 * 7, 8)), 1.5); // vertex 7's x
  // the first triangle (0, 1, 6): 000 100 011 -> bits from the lowest: byte 0 = 0b10001000
  EXPECT_EQ(static_cast<unsigned char>(b[64 + 128 + 14]), 0x88u);
}

TEST(BinaryMesh, RefusesTruncatedExtendedAndTamperedFilesNamingThem) {
  const auto m = random_triangle_soup(3, 300, 500);
  const auto p = pdd::test::temp_path("bad.pddm");
  pdd::write_binary_mesh(p, m);
  const std::string good = read_bytes(p);
  std::size_t refused = 0;
  for (const std::size_t keep : {std::size_t{0}, std::size_t{8}, std::size_t{63}, std::size_t{64},
                                 good.size() / 2, good.size() - 1}) {
    write_bytes(p, good.substr(0, keep));
    expect_refused(p, keep < 64 ? "too short" : "truncated");
    ++refused;
  }
  write_bytes(p, good + '\0');
  expect_refused(p, "its header announces");
  // every byte after the header, changed, fails the checksum (or, in the header, a check)
  for (const std::size_t at : {std::size_t{64}, std::size_t{64 + 16 * 300}, good.size() - 1}) {
    std::string bad = good;
    bad[at] = static_cast<char>(bad[at] ^ 0x10);
    write_bytes(p, bad);
    expect_refused(p, "checksum mismatch");
    ++refused;
  }
  std::string magic = good;
  magic[0] = 'Q';
  write_bytes(p, magic);
  expect_refused(p, "not a pdd binary mesh (wrong magic bytes)");
  std::string version = good;
  version[8] = 2;
  write_bytes(p, version);
  expect_refused(p, "binary mesh version 2; this reader reads version 1 only");
  std::string counts = good;
  counts[16] = static_cast<char>(counts[16] + 1); // one more vertex than stored
  write_bytes(p, counts);
  expect_refused(p, "bytes");
  EXPECT_EQ(refused, 9u);
  const auto missing = pdd::test::temp_path("no_such.pddm");
  expect_refused(missing, "cannot open");
}

/// `bytes` with its checksum recomputed (a file made by someone who knows the format).
std::string with_checksum(std::string bytes) {
  const std::string_view all(bytes);
  std::uint64_t h = pdd::detail::fnv1a64(all.substr(64), pdd::detail::fnv1a64(all.substr(0, 56)));
  for (int i = 0; i < 8; ++i, h >>= 8)
    bytes[56 + static_cast<std::size_t>(i)] = static_cast<char>(h & 0xff);
  return bytes;
}

// Bad content behind a valid checksum: a NaN coordinate, a vertex index past n (9-bit indices
// for 300 vertices reach 511), non-zero padding bits, a marker run past its count.
TEST(BinaryMesh, RefusesBadContentBehindAValidChecksum) {
  const auto m = random_triangle_soup(4, 300, 501); // 1503 indices x 9 bits: 5 padding bits
  const auto p = pdd::test::temp_path("content.pddm");
  pdd::write_binary_mesh(p, m);
  const std::string good = read_bytes(p);
  write_bytes(p, with_checksum(good));
  EXPECT_NO_THROW((void)pdd::read_binary_mesh(p));
  std::string nan = good;
  nan[64 + 6] = '\xf8';
  nan[64 + 7] = '\x7f'; // vertex 0's x: 0x7ff8... (a quiet NaN)
  write_bytes(p, with_checksum(nan));
  expect_refused(p, "vertex 0 has a non-finite coordinate");
  const std::size_t connectivity = good.size() - (3 * 501 * 9 + 7) / 8;
  std::string index = good;
  index[connectivity] = '\xff';
  index[connectivity + 1] = static_cast<char>(index[connectivity + 1] | 1); // first index 511
  write_bytes(p, with_checksum(index));
  expect_refused(p, "triangle 0 refers to missing vertex 511");
  std::string padding = good;
  padding.back() = static_cast<char>(padding.back() | 0x80);
  write_bytes(p, with_checksum(padding));
  expect_refused(p, "padding is not zero");
  std::string run = good; // the vertex marker section starts with a run: make it 127 longer
  run[64 + 16 * 300] = static_cast<char>(run[64 + 16 * 300] + 127);
  write_bytes(p, with_checksum(run));
  expect_refused(p, "the vertex marker section");
}

// Random changes behind a valid checksum (what a fuzzer would find once past it): 1 to 4 random
// bytes anywhere, header included; every file is either read (then every index is a vertex) or
// refused with pdd::error naming it. Never a crash or a read past the end (ASan in CI).
TEST(BinaryMesh, RandomChangesAreReadOrRefusedCleanly) {
  const auto m = random_triangle_soup(5, 200, 350);
  const auto p = pdd::test::temp_path("mutated.pddm");
  pdd::write_binary_mesh(p, m);
  const std::string good = read_bytes(p);
  std::mt19937 rng(2026);
  std::uniform_int_distribution<std::size_t> where(0, good.size() - 1);
  std::uniform_int_distribution<int> byte(0, 255), how_many(1, 4);
  std::size_t read = 0, refused = 0;
  for (int trial = 0; trial < 500; ++trial) {
    std::string bad = good;
    for (int k = how_many(rng); k > 0; --k)
      bad[where(rng)] = static_cast<char>(byte(rng));
    write_bytes(p, with_checksum(bad));
    try {
      const pdd::triangle_mesh r = pdd::read_binary_mesh(p);
      for (const auto& t : r.triangles)
        for (const pdd::index_t v : t)
          ASSERT_LT(v, r.vertices.size());
      ASSERT_EQ(r.vertex_markers.size(), r.vertices.size());
      ASSERT_EQ(r.triangle_markers.size(), r.triangles.size());
      ++read;
    } catch (const pdd::error& e) {
      ASSERT_EQ(std::string(e.what()).rfind(p.string() + ": ", 0), 0u) << e.what();
      ++refused;
    }
  }
  EXPECT_EQ(read + refused, 500u);
  EXPECT_GT(read, 25u);    // changed coordinates, markers and indices are still a mesh
  EXPECT_GT(refused, 25u); // changed header fields, varints and padding are not
}

TEST(BinaryMesh, IndexRoundTripAndRefusals) {
  const auto dir = pdd::test::fresh_dir("pddi");
  const auto p = dir / "mesh.pddi";
  pdd::write_binary_mesh_index(p, {"subdomain_0.pddm", "sub dir/subdomain_1.pddm"});
  EXPECT_EQ(pdd::test::read_text(p),
            "pdd-mesh-index 1\npieces 2\nsubdomain_0.pddm\nsub dir/subdomain_1.pddm\n");
  const auto pieces = pdd::read_binary_mesh_index(p);
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_EQ(pieces[1], dir / "sub dir/subdomain_1.pddm");
  EXPECT_THROW(pdd::write_binary_mesh_index(p, {}), pdd::error);
  EXPECT_THROW(pdd::write_binary_mesh_index(p, {"a\nb"}), pdd::error);
  EXPECT_THROW(pdd::write_binary_mesh_index(p, {"/abs.pddm"}), pdd::error);
  const auto refused = [&](const std::string& text, const std::string& what) {
    pdd::test::write_text(p, text);
    try {
      (void)pdd::read_binary_mesh_index(p);
      ADD_FAILURE() << "accepted: " << text;
    } catch (const pdd::error& e) {
      EXPECT_NE(std::string(e.what()).find(p.string() + ":" + what), std::string::npos) << e.what();
    }
  };
  refused("<?xml version=\"1.0\"?>\n", "1: not a pdd mesh index");
  refused("pdd-mesh-index 2\npieces 1\na.pddm\n", "1: index version '2'");
  refused("pdd-mesh-index 1\npieces 0\n", "2: expected 'pieces N'");
  refused("pdd-mesh-index 1\npieces 3\na.pddm\nb.pddm\n", "5: the index announces 3 pieces");
  refused("pdd-mesh-index 1\npieces 1\na.pddm\nb.pddm\n", "4: more lines");
  refused("pdd-mesh-index 1\npieces 1\n/a.pddm\n", "3: empty or absolute");
}

TEST(PieceFiles, ReadersTellTheFormatFromTheFile) {
  const auto dir = pdd::test::fresh_dir("piece_files");
  const auto m = pdd::test::small_mesh();
  for (const auto f : {pdd::piece_format::vtu, pdd::piece_format::binary}) {
    const auto piece = dir / pdd::piece_file_name(3, f);
    pdd::write_piece(piece, m, f);
    pdd::write_piece_index(dir / pdd::piece_index_name(f), {piece.filename().string()}, f);
    EXPECT_EQ(pdd::detect_piece_format(piece), f);
    EXPECT_EQ(pdd::read_piece_index(dir / pdd::piece_index_name(f)), std::vector<fs::path>{piece});
    expect_bitwise_equal(pdd::read_piece(piece), m); // neither format stores segments
  }
  EXPECT_EQ(pdd::piece_file_name(12, pdd::piece_format::binary), "subdomain_12.pddm");
  pdd::test::write_text(dir / "junk", "hello");
  EXPECT_THROW((void)pdd::read_piece(dir / "junk"), pdd::error);
  // the disk estimate: binary well under half of VTU's, both about 14 and 35 bytes per triangle
  const double vtu = pdd::estimated_piece_bytes(pdd::piece_format::vtu, 1e8, 1600);
  const double bin = pdd::estimated_piece_bytes(pdd::piece_format::binary, 1e8, 1600);
  EXPECT_NEAR(vtu / 1e8, 35.0, 1.0);
  EXPECT_NEAR(bin / 1e8, 13.6, 0.6);
}

} // namespace binary_mesh_test
