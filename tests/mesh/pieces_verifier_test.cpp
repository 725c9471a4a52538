// Tests of pdd::pieces_verifier and pdd::verifying_sink (pdd-mesh --verify with
// --output-per-subdomain): the subdomain meshes of a decoupled run pass, in any order and added
// from several threads at once, with every interface edge matched; a verifying_sink in front of
// another sink verifies what that sink receives and hands every mesh on; tampered pieces (an
// edge flipped across an interface, an interface vertex moved by one ulp) fail with the same
// counts in any order; an area bound tighter than the mesh's fails on every piece.
#include <pdd/generate.hpp>
#include <pdd/geometry/model_domains.hpp>
#include <pdd/mesh/verifying_sink.hpp>

#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include "tampered_pieces.hpp"

#include <algorithm>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace pieces_verifier_test {
namespace {

// Keeps every subdomain mesh by id (consume may run concurrently).
struct collecting_sink {
  std::mutex mutex;
  std::vector<pdd::triangle_mesh> pieces;
  std::size_t finished = 0;
  void start(pdd::index_t n) { pieces.resize(n); }
  void consume(pdd::index_t id, pdd::triangle_mesh&& m) {
    const std::scoped_lock lock(mutex);
    pieces.at(id) = std::move(m);
  }
  void finish() { ++finished; }
};

pdd::generate_options options_for(double max_area) {
  pdd::generate_options o;
  o.criteria.max_area = max_area;
  o.subdomains = 16;
  o.threads = 2;
  return o;
}

std::vector<pdd::triangle_mesh> pieces_of(const pdd::pslg& domain, double max_area) {
  collecting_sink sink;
  pdd::generate(domain, options_for(max_area), sink);
  return std::move(sink.pieces);
}

std::string name(std::size_t k) {
  return "piece " + std::to_string(k);
}

// The report over the pieces added in the order `order`.
pdd::pieces_report verify_in_order(const pdd::pslg& domain, double max_area,
                                   const std::vector<pdd::triangle_mesh>& pieces,
                                   const std::vector<std::size_t>& order) {
  pdd::pieces_verifier v(domain, {.criteria = {.max_area = max_area}});
  for (const std::size_t k : order)
    v.add(static_cast<std::uint32_t>(k), name(k), pieces[k]);
  return v.finish();
}

std::vector<std::size_t> forward(std::size_t n) {
  std::vector<std::size_t> order(n);
  for (std::size_t k = 0; k < n; ++k)
    order[k] = k;
  return order;
}

std::vector<std::size_t> backward(std::size_t n) {
  auto order = forward(n);
  std::reverse(order.begin(), order.end());
  return order;
}

// Every count of two reports (not the messages, whose order follows the matching).
void expect_same_counts(const pdd::pieces_report& a, const pdd::pieces_report& b) {
  EXPECT_EQ(a.pieces, b.pieces);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.interface_edges, b.interface_edges);
  EXPECT_EQ(a.domain_boundary_edges, b.domain_boundary_edges);
  EXPECT_EQ(a.delaunay_violations, b.delaunay_violations);
  EXPECT_EQ(a.area_violations, b.area_violations);
  EXPECT_EQ(a.quality_violations, b.quality_violations);
  EXPECT_EQ(a.interface_overlaps, b.interface_overlaps);
  EXPECT_EQ(a.interface_delaunay_violations, b.interface_delaunay_violations);
  EXPECT_EQ(a.unmatched_edges, b.unmatched_edges);
  EXPECT_NEAR(a.area_mesh, b.area_mesh, 1e-12 * a.area_domain);
}

} // namespace

TEST(PiecesVerifier, DecoupledPiecesPassInAnyOrderAndFromManyThreads) {
  for (const pdd::pslg& domain : {pdd::key_domain(), pdd::pipe_domain()}) {
    const auto pieces = pieces_of(domain, 1e-3);
    ASSERT_EQ(pieces.size(), 16u);
    const auto r = verify_in_order(domain, 1e-3, pieces, forward(pieces.size()));
    EXPECT_TRUE(r.ok()) << (r.messages.empty() ? "" : r.messages[0]);
    EXPECT_EQ(r.interface_edges, pdd::test::interface_edges(pieces).size());
    EXPECT_GT(r.interface_edges, 50u);
    expect_same_counts(r, verify_in_order(domain, 1e-3, pieces, backward(pieces.size())));
    pdd::pieces_verifier parallel(domain, {.criteria = {.max_area = 1e-3}});
    tbb::parallel_for(std::size_t{0}, pieces.size(), [&](std::size_t k) {
      parallel.add(static_cast<std::uint32_t>(k), name(k), pieces[k]);
    });
    expect_same_counts(r, parallel.finish());
  }
}

TEST(PiecesVerifier, AVerifyingSinkVerifiesWhatItHandsOn) {
  const pdd::pslg domain = pdd::pipe_domain();
  collecting_sink inner;
  pdd::pieces_verifier verifier(domain, {.criteria = {.max_area = 1e-3}});
  pdd::verifying_sink sink(inner, verifier, [](pdd::index_t id) { return name(id); });
  pdd::generate(domain, options_for(1e-3), sink);
  const pdd::pieces_report r = verifier.finish();
  EXPECT_EQ(inner.finished, 1u);
  ASSERT_EQ(inner.pieces.size(), 16u);
  EXPECT_TRUE(r.ok()) << (r.messages.empty() ? "" : r.messages[0]);
  EXPECT_EQ(r.pieces, 16u);
  std::size_t triangles = 0;
  for (const auto& p : inner.pieces)
    triangles += p.triangles.size();
  EXPECT_EQ(r.triangles, triangles);
  EXPECT_EQ(r.interface_edges, pdd::test::interface_edges(inner.pieces).size());
  EXPECT_GE(sink.seconds(), 0.0);
}

TEST(PiecesVerifier, AnEdgeFlippedAcrossAnInterfaceFailsInAnyOrder) {
  const pdd::pslg domain = pdd::key_domain();
  auto pieces = pieces_of(domain, 1e-3);
  const auto [p, q] = pdd::test::flip_an_interface_edge(pieces);
  ASSERT_LT(p, pieces.size()) << "no interface edge with a convex quadrilateral";
  const auto r = verify_in_order(domain, 1e-3, pieces, forward(pieces.size()));
  EXPECT_FALSE(r.ok());
  EXPECT_GE(r.interface_delaunay_violations, 1u);
  const bool named = std::any_of(r.messages.begin(), r.messages.end(), [&](const auto& m) {
    return m.find("not locally Delaunay across the interface") != std::string::npos;
  });
  EXPECT_TRUE(named) << (r.messages.empty() ? "" : r.messages[0]);
  expect_same_counts(r, verify_in_order(domain, 1e-3, pieces, backward(pieces.size())));
}

TEST(PiecesVerifier, AnInterfaceVertexMovedByOneUlpFailsInAnyOrder) {
  const pdd::pslg domain = pdd::pipe_domain();
  auto pieces = pieces_of(domain, 1e-3);
  const pdd::test::edge_side s = pdd::test::move_an_interface_vertex(pieces);
  const auto r = verify_in_order(domain, 1e-3, pieces, forward(pieces.size()));
  EXPECT_FALSE(r.ok());
  EXPECT_GE(r.unmatched_edges, 2u); // the moved edge's two sides match nothing
  const std::string where = name(s.piece) + ": triangle " + std::to_string(s.triangle) + ", edge";
  const bool named = std::any_of(r.messages.begin(), r.messages.end(),
                                 [&](const auto& m) { return m.find(where) != std::string::npos; });
  EXPECT_TRUE(named) << (r.messages.empty() ? "" : r.messages[0]);
  expect_same_counts(r, verify_in_order(domain, 1e-3, pieces, backward(pieces.size())));
}

TEST(PiecesVerifier, ATighterAreaBoundFailsOnThePieces) {
  const pdd::pslg domain = pdd::key_domain();
  const auto pieces = pieces_of(domain, 1e-3);
  const auto r = verify_in_order(domain, 1e-4, pieces, forward(pieces.size()));
  EXPECT_FALSE(r.ok());
  EXPECT_GT(r.area_violations, 0u);
  EXPECT_EQ(r.unmatched_edges, 0u);
  EXPECT_EQ(r.interface_delaunay_violations, 0u);
}

} // namespace pieces_verifier_test
