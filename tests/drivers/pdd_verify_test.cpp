// pdd-verify end to end: a per-subdomain output of pdd-mesh passes; tampered copies (an edge
// flipped across an interface, an interface vertex moved by one ulp in one piece, a truncated
// piece) are found and named.
#include <pdd/io/vtu.hpp>
#include <pdd/io/vtu_read.hpp>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "test_files.hpp"
#include "test_support.hpp"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

pdd::test::command_result run(const std::string& exe, const std::string& args) {
  return pdd::test::run_command("'" + exe + "' " + args);
}

/// Meshes `poly` into 16 per-subdomain pieces under a fresh folder; returns the folder.
fs::path mesh_pieces(const std::string& poly, const std::string& max_area, const std::string& tag) {
  const fs::path dir = pdd::test::fresh_dir(tag) / "out";
  const auto r =
      run(PDD_MESH_EXE, pdd::test::bundled_data(poly).string() + " --max-area " + max_area +
                            " --subdomains 16 -q --output-per-subdomain " + dir.string());
  EXPECT_EQ(r.code, 0) << r.output;
  return dir;
}

pdd::test::command_result verify(const fs::path& dir, const std::string& poly,
                                 const std::string& extra = "") {
  return run(PDD_VERIFY_EXE, (dir / "mesh.pvtu").string() + " " +
                                 pdd::test::bundled_data(poly).string() + " " + extra);
}

using point_bits = std::array<std::uint64_t, 2>;
point_bits bits(const pdd::point& p) {
  return {std::bit_cast<std::uint64_t>(p.x), std::bit_cast<std::uint64_t>(p.y)};
}

/// One side of an interface edge: piece, triangle, and the position of the edge's first
/// vertex in the triangle (the edge runs tri[i] -> tri[i + 1]).
struct side {
  std::size_t piece, triangle;
  int i;
};

/// The interface edges of the pieces: directed edge (from, to) of one piece whose reverse is
/// in another piece; returns pairs (this side, the other side).
std::vector<std::pair<side, side>> interface_edges(const std::vector<pdd::triangle_mesh>& pieces) {
  std::map<std::pair<point_bits, point_bits>, side> directed;
  for (std::size_t k = 0; k < pieces.size(); ++k)
    for (std::size_t t = 0; t < pieces[k].triangles.size(); ++t)
      for (int i = 0; i < 3; ++i) {
        const auto& tri = pieces[k].triangles[t];
        directed[{bits(pieces[k].vertices[tri[i]]), bits(pieces[k].vertices[tri[(i + 1) % 3]])}] = {
            k, t, i};
      }
  std::vector<std::pair<side, side>> out;
  for (const auto& [edge, s] : directed) {
    const auto other = directed.find({edge.second, edge.first});
    if (other != directed.end() && other->second.piece != s.piece && edge.first < edge.second)
      out.push_back({s, other->second});
  }
  return out;
}

std::vector<pdd::triangle_mesh> read_pieces(const fs::path& dir) {
  std::vector<pdd::triangle_mesh> pieces;
  for (const fs::path& p : pdd::read_pvtu(dir / "mesh.pvtu"))
    pieces.push_back(pdd::read_vtu(p));
  return pieces;
}

fs::path piece_path(std::size_t k) {
  return "subdomain_" + std::to_string(k) + ".vtu";
}

} // namespace

TEST(PddVerify, PerSubdomainOutputsOfKeyAndPipePass) {
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
    const auto pieces = read_pieces(dir);
    for (const auto& p : pieces)
      triangles += p.triangles.size();
    EXPECT_EQ(j["triangles"], triangles);
    EXPECT_EQ(j["interface_edges"], interface_edges(pieces).size());
    EXPECT_GT(j["interface_edges"].get<std::size_t>(), 50u) << poly;
    EXPECT_GT(j["domain_boundary_edges"].get<std::size_t>(), 50u) << poly;
    // A tighter area bound than the mesh was made for fails, with code 3.
    const auto tight = verify(dir, poly, "--max-area 1e-4");
    EXPECT_EQ(tight.code, 3) << tight.output;
    EXPECT_NE(tight.output.find("area above the bound"), std::string::npos) << tight.output;
  }
}

TEST(PddVerify, FindsAnEdgeFlippedAcrossAnInterface) {
  const fs::path dir = mesh_pieces("key.poly", "1e-3", "flip");
  auto pieces = read_pieces(dir);
  const auto edges = interface_edges(pieces);
  ASSERT_FALSE(edges.empty());
  std::size_t flipped = pieces.size();
  for (const auto& [p, q] : edges) {
    // p's triangle runs a -> b -> c, q's runs b -> a -> d; flipped: (a, d, c) in p's piece and
    // (d, b, c) in q's piece (each piece gains the other's apex), if both turn left.
    auto& mp = pieces[p.piece];
    auto& mq = pieces[q.piece];
    const auto& tp = mp.triangles[p.triangle];
    const auto& tq = mq.triangles[q.triangle];
    const pdd::point a = mp.vertices[tp[p.i]], b = mp.vertices[tp[(p.i + 1) % 3]],
                     c = mp.vertices[tp[(p.i + 2) % 3]], d = mq.vertices[tq[(q.i + 2) % 3]];
    const auto left = [](const pdd::point& u, const pdd::point& v, const pdd::point& w) {
      return (v.x - u.x) * (w.y - u.y) - (v.y - u.y) * (w.x - u.x) > 1e-12;
    };
    if (!left(a, d, c) || !left(d, b, c)) continue;
    const auto add = [](pdd::triangle_mesh& m, const pdd::point& v) {
      m.vertices.push_back(v);
      m.vertex_markers.push_back(0);
      return static_cast<pdd::index_t>(m.vertices.size() - 1);
    };
    mp.triangles[p.triangle] = {tp[p.i], add(mp, d), tp[(p.i + 2) % 3]};
    const pdd::index_t qb = tq[q.i], qc = add(mq, c);
    mq.triangles[q.triangle] = {tq[(q.i + 2) % 3], qb, qc};
    pdd::write_vtu(dir / piece_path(p.piece), mp);
    pdd::write_vtu(dir / piece_path(q.piece), mq);
    flipped = p.piece;
    break;
  }
  ASSERT_LT(flipped, pieces.size()) << "no interface edge with a convex quadrilateral";
  const auto r = verify(dir, "key.poly", "--max-area 1e-3");
  EXPECT_EQ(r.code, 3) << r.output;
  EXPECT_NE(r.output.find("not locally Delaunay across the interface"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find(piece_path(flipped).string() + ": triangle"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("verification FAILED"), std::string::npos) << r.output;
}

TEST(PddVerify, FindsAnInterfaceVertexMovedByOneUlp) {
  const fs::path dir = mesh_pieces("pipe.poly", "1e-3", "ulp");
  auto pieces = read_pieces(dir);
  const auto edges = interface_edges(pieces);
  ASSERT_FALSE(edges.empty());
  const side s = edges[edges.size() / 2].first;
  auto& m = pieces[s.piece];
  pdd::point& v = m.vertices[m.triangles[s.triangle][s.i]];
  v.x = std::nextafter(v.x, INFINITY);
  pdd::write_vtu(dir / piece_path(s.piece), m);
  const auto r = verify(dir, "pipe.poly", "--max-area 1e-3");
  EXPECT_EQ(r.code, 3) << r.output;
  EXPECT_NE(r.output.find(piece_path(s.piece).string() + ": triangle " +
                          std::to_string(s.triangle) + ", edge"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("in no other piece (with bitwise equal endpoints)"), std::string::npos)
      << r.output;
}

TEST(PddVerify, TruncatedOrMissingPieceIsACleanError) {
  const fs::path dir = mesh_pieces("key.poly", "1e-3", "cut");
  const fs::path piece = dir / piece_path(5);
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
