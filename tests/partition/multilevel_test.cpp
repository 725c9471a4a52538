// The building blocks of the multilevel bisection: working-graph construction, contraction,
// matching, FM refinement, exact bisection and the initial bisection.
#include "partition_graphs.hpp"
#include "test_support.hpp"

#include <pdd/partition/bisection_metrics.hpp>
#include <pdd/partition/detail/coarsen.hpp>
#include <pdd/partition/detail/csr.hpp>
#include <pdd/partition/detail/exact.hpp>
#include <pdd/partition/detail/fm.hpp>
#include <pdd/partition/detail/initial.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

namespace multilevel_test {
namespace {

using namespace pdd::detail;
using pdd::partition_graph;
using namespace pdd::test;

// Every arc has its reverse with the bitwise same weight; no self loops, no parallel arcs.
void expect_symmetric_simple(const ml_graph& g) {
  for (const auto e : boost::make_iterator_range(boost::edges(g))) {
    const std::size_t u = boost::source(e, g), v = boost::target(e, g);
    ASSERT_NE(u, v);
    const auto [back, found] = boost::edge(v, u, g);
    ASSERT_TRUE(found);
    EXPECT_EQ(g[back].weight, g[e].weight);
  }
  for (std::size_t v = 0; v < boost::num_vertices(g); ++v) {
    std::vector<std::size_t> targets;
    for (const auto e : boost::make_iterator_range(boost::out_edges(v, g)))
      targets.push_back(boost::target(e, g));
    EXPECT_TRUE(std::adjacent_find(targets.begin(), targets.end()) == targets.end());
  }
}

TEST(WorkingGraph, MergesParallelEdgesAndDropsSelfLoops) {
  partition_graph g = path_graph(4);
  add(g, 1, 2, 0.25), add(g, 2, 1, 0.5), add(g, 3, 3, 9.0);
  const ml_graph mg = to_ml_graph(g);
  expect_symmetric_simple(mg);
  EXPECT_EQ(boost::num_edges(mg), 6u);
  EXPECT_EQ(mg[boost::edge(std::size_t{1}, std::size_t{2}, mg).first].weight, 1.75);
  const std::vector<std::uint8_t> part{0, 1, 0, 1};
  EXPECT_EQ(ml_cut(mg, part), pdd::cut_weight(g, part));
}

TEST(Coarsening, ContractionPreservesWeightsAndCuts) {
  for (std::uint64_t seed = 0; seed < 30; ++seed) {
    const ml_graph g =
        to_ml_graph(seed % 2 ? random_holey_grid(seed) : madd_like_graph(150, 0.3, seed));
    std::mt19937_64 rng(seed);
    const auto match = heavy_edge_matching(g, rng, 1e300);
    std::size_t matched = 0;
    for (std::size_t v = 0; v < match.size(); ++v) {
      ASSERT_EQ(match[match[v]], v); // an involution
      if (match[v] != v) {
        ++matched;
        EXPECT_TRUE(boost::edge(v, match[v], g).second);
      }
    }
    EXPECT_GT(matched, match.size() / 2) << seed; // heavy-edge matching pairs most vertices
    const coarse_level level = contract(g, match);
    expect_symmetric_simple(level.graph);
    EXPECT_NEAR(total_vertex_weight(level.graph), total_vertex_weight(g), 1e-9);
    std::vector<std::uint8_t> coarse(boost::num_vertices(level.graph));
    for (std::size_t c = 0; c < coarse.size(); ++c)
      coarse[c] = static_cast<std::uint8_t>(rng() % 2);
    std::vector<std::uint8_t> fine(boost::num_vertices(g));
    for (std::size_t v = 0; v < fine.size(); ++v)
      fine[v] = coarse[level.fine_to_coarse[v]];
    EXPECT_NEAR(ml_cut(level.graph, coarse), ml_cut(g, fine), 1e-9) << seed;
  }
}

TEST(Coarsening, MatchingRespectsTheVertexWeightCap) {
  const ml_graph g = to_ml_graph(grid_graph(10, 10));
  std::mt19937_64 rng(1);
  const auto match = heavy_edge_matching(g, rng, 1.5); // unit vertices: no pair fits
  for (std::size_t v = 0; v < match.size(); ++v)
    EXPECT_EQ(match[v], v);
}

TEST(Refinement, FmNeverWorsensAndOftenImproves) {
  int improved = 0;
  for (std::uint64_t seed = 0; seed < 40; ++seed) {
    const ml_graph g = to_ml_graph(random_holey_grid(seed));
    const double bound = 0.55 * total_vertex_weight(g);
    const part_limits max_weight{bound, bound};
    std::mt19937_64 rng(seed);
    std::vector<std::uint8_t> part(boost::num_vertices(g));
    for (auto& p : part)
      p = static_cast<std::uint8_t>(rng() % 2);
    const bisection_score before = score_bisection(g, part, max_weight);
    const bisection_score after = fm_refine(g, part, max_weight, 8);
    EXPECT_FALSE(before < after) << seed;
    EXPECT_EQ(after.cut, score_bisection(g, part, max_weight).cut);
    improved += after < before;
    EXPECT_EQ(after.excess, 0.0) << seed; // random halves are nearly balanced: FM balances
  }
  EXPECT_EQ(improved, 40);
}

TEST(ExactBisection, MatchesAnIndependentEnumeration) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> weight(0.0, 2.0);
  for (int trial = 0; trial < 40; ++trial) {
    const std::size_t n = 2 + static_cast<std::size_t>(trial % 11);
    partition_graph g = with_vertices(n);
    for (std::size_t v = 0; v < n; ++v)
      g[v].weight = weight(rng);
    for (std::size_t k = 0; k < 2 * n; ++k)
      add(g, rng() % n, rng() % n, weight(rng));
    const double fraction = trial % 2 ? 0.55 : 0.7;
    const ml_graph mg = to_ml_graph(g);
    // even shares, and (every third trial) part 0 a third of the weight
    const double share = trial % 3 == 0 ? 1.0 / 3.0 : 0.5;
    const part_limits max_weight = part_weight_limits(
        pdd::bisection_options{.max_part_fraction = fraction, .target_fraction = share},
        total_vertex_weight(mg));
    const auto part = exact_bisection(mg, max_weight);
    bisection_score best{1e300, 1e300};
    for (std::uint32_t mask = 1; mask + 1 < (1U << n); ++mask) {
      std::vector<std::uint8_t> p(n);
      for (std::size_t v = 0; v < n; ++v)
        p[v] = static_cast<std::uint8_t>(mask >> v & 1U);
      const bisection_score s = score_bisection(mg, p, max_weight);
      if (s < best) best = s;
    }
    const bisection_score got = score_bisection(mg, part, max_weight);
    EXPECT_NEAR(got.excess, best.excess, 1e-12) << trial;
    EXPECT_NEAR(got.cut, best.cut, 1e-12) << trial;
    if (share == 0.5) {
      EXPECT_EQ(part[0], 0);
    }
  }
}

TEST(InitialBisection, GrowingCoversOneSideAndStaysNonEmpty) {
  const ml_graph g = to_ml_graph(grid_graph(10, 7));
  const double total = total_vertex_weight(g);
  for (std::size_t seed_vertex : {0, 31, 69}) {
    const auto grown =
        grow_bisection(g, seed_vertex, 0.5 * total, part_limits{0.55 * total, 0.55 * total});
    const auto w = ml_part_weights(g, grown);
    EXPECT_GE(w[1], 0.5 * total);
    EXPECT_LE(w[1], 0.55 * total);
    EXPECT_EQ(grown[seed_vertex], 1);
    const auto bfs = bfs_bisection(g, seed_vertex, 0.5 * total);
    EXPECT_GE(ml_part_weights(g, bfs)[1], 0.5 * total);
  }
  std::mt19937_64 rng(3);
  const auto part = initial_bisection(g, part_limits{0.55 * total, 0.55 * total}, 8, 8, rng);
  EXPECT_EQ(ml_cut(g, part), 7.0); // a straight cut across the short side
  // part 1 two thirds of the weight: still a straight cut across, at column 3 or 4 of 10
  const part_limits third =
      part_weight_limits(pdd::bisection_options{.target_fraction = 0.3}, total);
  const auto uneven = initial_bisection(g, third, 8, 8, rng);
  EXPECT_EQ(ml_cut(g, uneven), 7.0);
  EXPECT_NEAR(ml_part_weights(g, uneven)[0], 0.3 * total, 0.05 * total);
}

TEST(Randomness, PermutationsArePortableAndComplete) {
  std::mt19937_64 a(mix_seed(5, 0)), b(mix_seed(5, 0)), c(mix_seed(5, 1));
  const auto pa = random_permutation(100, a), pb = random_permutation(100, b);
  EXPECT_EQ(pa, pb);
  EXPECT_NE(pa, random_permutation(100, c));
  std::vector<std::size_t> sorted = pa;
  std::sort(sorted.begin(), sorted.end());
  for (std::size_t i = 0; i < 100; ++i)
    EXPECT_EQ(sorted[i], i);
}

} // namespace

} // namespace multilevel_test
