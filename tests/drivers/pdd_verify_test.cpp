// pdd-verify end to end, for both per-subdomain formats (VTU: .vtu pieces and mesh.pvtu;
// binary: .pddm pieces and mesh.pddi): a per-subdomain output of pdd-mesh passes; tampered
// copies (an edge flipped across an interface, an interface vertex moved by one ulp in one
// piece, a truncated piece) are found and named. A tampered binary piece is written back through
// the library (a valid checksum: only its geometry is wrong).
#include <pdd/io/piece_files.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tampered_pieces.hpp"
#include "test_files.hpp"
#include "test_support.hpp"

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace pdd_verify_test {
namespace fs = std::filesystem;

namespace {

pdd::test::command_result run(const std::string& exe, const std::string& args) {
  return pdd::test::run_command("'" + exe + "' " + args);
}

/// The tests run once per format.
class PddVerify : public ::testing::TestWithParam<pdd::piece_format> {
protected:
  pdd::piece_format format() const { return GetParam(); }
  std::string format_name() const { return pdd::to_string(format()); }

  /// Meshes `poly` into 16 per-subdomain pieces under a fresh folder; returns the folder.
  fs::path mesh_pieces(const std::string& poly, const std::string& max_area,
                       const std::string& tag) const {
    const fs::path dir = pdd::test::fresh_dir(tag + "_" + format_name()) / "out";
    const auto r = run(PDD_MESH_EXE, pdd::test::bundled_data(poly).string() + " --max-area " +
                                         max_area + " --subdomains 16 -q --format " +
                                         format_name() + " --output-per-subdomain " + dir.string());
    EXPECT_EQ(r.code, 0) << r.output;
    EXPECT_TRUE(fs::exists(index(dir))) << r.output;
    return dir;
  }

  fs::path index(const fs::path& dir) const { return dir / pdd::piece_index_name(format()); }

  std::string piece_name(std::size_t k) const {
    return pdd::piece_file_name(static_cast<pdd::index_t>(k), format());
  }

  /// Writes piece k back into dir in the test's format.
  void write_back(const fs::path& dir, std::size_t k, const pdd::triangle_mesh& m) const {
    pdd::write_piece(dir / piece_name(k), m, format());
  }

  pdd::test::command_result verify(const fs::path& dir, const std::string& poly,
                                   const std::string& extra = "") const {
    return run(PDD_VERIFY_EXE,
               index(dir).string() + " " + pdd::test::bundled_data(poly).string() + " " + extra);
  }
};

} // namespace

TEST_P(PddVerify, PerSubdomainOutputsOfKeyAndPipePass) {
  for (const char* poly : {"key.poly", "pipe.poly"}) {
    const fs::path dir = mesh_pieces(poly, "1e-3", poly);
    const fs::path stats = dir.parent_path() / "verify.json";
    const auto r = verify(dir, poly, "--max-area 1e-3 --stats " + stats.string());
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_NE(r.output.find("verification passed"), std::string::npos) << r.output;
    std::ifstream in(stats);
    const auto j = nlohmann::json::parse(in);
    EXPECT_EQ(j["pieces"], 16);
    EXPECT_EQ(j["ok"], true);
    std::size_t triangles = 0;
    const auto pieces = pdd::test::read_all_pieces(index(dir));
    for (const auto& p : pieces)
      triangles += p.triangles.size();
    EXPECT_EQ(j["triangles"], triangles);
    EXPECT_EQ(j["interface_edges"], pdd::test::interface_edges(pieces).size());
    EXPECT_GT(j["interface_edges"].get<std::size_t>(), 50u) << poly;
    EXPECT_GT(j["domain_boundary_edges"].get<std::size_t>(), 50u) << poly;
    // A tighter area bound than the mesh was made for fails, with code 3.
    const auto tight = verify(dir, poly, "--max-area 1e-4");
    EXPECT_EQ(tight.code, 3) << tight.output;
    EXPECT_NE(tight.output.find("area above the bound"), std::string::npos) << tight.output;
  }
}

TEST_P(PddVerify, PddMeshVerifiesItsPiecesInMemoryAsPddVerifyDoes) {
  // pdd-mesh --verify --output-per-subdomain checks every piece before it is written
  // (pdd::verifying_sink): the same interface edges as pdd-verify reading the files back.
  for (const char* poly : {"key.poly", "pipe.poly"}) {
    const fs::path dir = pdd::test::fresh_dir(std::string("inmem_") + format_name()) / "out";
    const fs::path mesh_stats = dir.parent_path() / "mesh.json";
    const auto m = run(PDD_MESH_EXE, pdd::test::bundled_data(poly).string() +
                                         " --max-area 1e-3 --subdomains 16 --verify --format " +
                                         format_name() + " --output-per-subdomain " + dir.string() +
                                         " --stats " + mesh_stats.string());
    ASSERT_EQ(m.code, 0) << m.output;
    EXPECT_NE(m.output.find("verification passed"), std::string::npos) << m.output;
    const fs::path verify_stats = dir.parent_path() / "verify.json";
    const auto v = verify(dir, poly, "--max-area 1e-3 --stats " + verify_stats.string());
    ASSERT_EQ(v.code, 0) << v.output;
    std::ifstream mesh_in(mesh_stats), verify_in(verify_stats);
    const auto jm = nlohmann::json::parse(mesh_in), jv = nlohmann::json::parse(verify_in);
    EXPECT_EQ(jm["verified"], true) << poly;
    EXPECT_EQ(jm["conforming"], true) << poly;
    EXPECT_EQ(jm["delaunay_violations"], 0) << poly;
    EXPECT_EQ(jm["interface_edges_verified"], jv["interface_edges"]) << poly;
    EXPECT_GT(jm["interface_edges_verified"].get<std::size_t>(), 50u) << poly;
    EXPECT_TRUE(jm["timings"].contains("verify")) << poly;
  }
}

TEST_P(PddVerify, FindsAnEdgeFlippedAcrossAnInterface) {
  const fs::path dir = mesh_pieces("key.poly", "1e-3", "flip");
  auto pieces = pdd::test::read_all_pieces(index(dir));
  const auto [p, q] = pdd::test::flip_an_interface_edge(pieces);
  ASSERT_LT(p, pieces.size()) << "no interface edge with a convex quadrilateral";
  write_back(dir, p, pieces[p]);
  write_back(dir, q, pieces[q]);
  const auto r = verify(dir, "key.poly", "--max-area 1e-3");
  EXPECT_EQ(r.code, 3) << r.output;
  EXPECT_NE(r.output.find("not locally Delaunay across the interface"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find(piece_name(p) + ": triangle"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("verification FAILED"), std::string::npos) << r.output;
}

TEST_P(PddVerify, FindsAnInterfaceVertexMovedByOneUlp) {
  const fs::path dir = mesh_pieces("pipe.poly", "1e-3", "ulp");
  auto pieces = pdd::test::read_all_pieces(index(dir));
  const pdd::test::edge_side s = pdd::test::move_an_interface_vertex(pieces);
  write_back(dir, s.piece, pieces[s.piece]);
  const auto r = verify(dir, "pipe.poly", "--max-area 1e-3");
  EXPECT_EQ(r.code, 3) << r.output;
  EXPECT_NE(
      r.output.find(piece_name(s.piece) + ": triangle " + std::to_string(s.triangle) + ", edge"),
      std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("in no other piece (with bitwise equal endpoints)"), std::string::npos)
      << r.output;
}

TEST_P(PddVerify, TruncatedOrMissingPieceIsACleanError) {
  const fs::path dir = mesh_pieces("key.poly", "1e-3", "cut");
  const fs::path piece = dir / piece_name(5);
  fs::resize_file(piece, fs::file_size(piece) / 2);
  const auto r = verify(dir, "key.poly");
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_NE(r.output.find("pdd-verify: error: " + piece.string()), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("truncated"), std::string::npos) << r.output;
  fs::remove(piece);
  const auto gone = verify(dir, "key.poly");
  EXPECT_EQ(gone.code, 1) << gone.output;
  EXPECT_NE(gone.output.find(piece.string() + ": cannot open"), std::string::npos) << gone.output;
  EXPECT_EQ(run(PDD_VERIFY_EXE, "").code, 2);
}

// A binary piece changed by one byte after it was written fails its checksum: exit code 1,
// the file named (never a verification of wrong data).
TEST(PddVerifyBinary, AByteChangedInAPieceFailsItsChecksum) {
  const fs::path dir = pdd::test::fresh_dir("byte_binary") / "out";
  ASSERT_EQ(run(PDD_MESH_EXE, pdd::test::bundled_data("key.poly").string() +
                                  " --max-area 1e-3 --subdomains 16 -q --format binary "
                                  "--output-per-subdomain " +
                                  dir.string())
                .code,
            0);
  const fs::path piece = dir / "subdomain_3.pddm";
  {
    std::fstream f(piece, std::ios::binary | std::ios::in | std::ios::out);
    f.seekp(64 + 7); // the last byte of vertex 0's x
    f.put('\x5a');
  }
  const auto r = run(PDD_VERIFY_EXE, (dir / "mesh.pddi").string() + " " +
                                         pdd::test::bundled_data("key.poly").string());
  EXPECT_EQ(r.code, 1) << r.output;
  EXPECT_NE(r.output.find("pdd-verify: error: " + piece.string() + ": checksum mismatch"),
            std::string::npos)
      << r.output;
}

INSTANTIATE_TEST_SUITE_P(Formats, PddVerify,
                         ::testing::Values(pdd::piece_format::vtu, pdd::piece_format::binary),
                         [](const auto& param_info) {
                           return std::string(pdd::to_string(param_info.param));
                         });

} // namespace pdd_verify_test
