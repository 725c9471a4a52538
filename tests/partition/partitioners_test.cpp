// Both GraphPartitioner models on graphs with known optimal cuts, balance, determinism, tiny
// graphs, parallel edges and self loops, extreme weights, and bad input.
#include "partition_graphs.hpp"
#include "test_support.hpp"

#include <pdd/partition/bisection_metrics.hpp>
#include <pdd/partition/boost_partitioner.hpp>
#include <pdd/partition/default_partitioner.hpp>
#include <pdd/partition/detail/metis_input.hpp>
#include <pdd/partition/metis.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <thread>
#include <vector>

namespace partitioners_test {
namespace {

using pdd::partition_graph;
using namespace pdd::test;

template <class P>
class Partitioner : public ::testing::Test {};

#ifdef PDD_HAVE_METIS
using partitioner_types = ::testing::Types<pdd::boost_partitioner, pdd::metis_partitioner>;
#else
using partitioner_types = ::testing::Types<pdd::boost_partitioner>;
#endif
TYPED_TEST_SUITE(Partitioner, partitioner_types);

// Checks the GraphPartitioner contract and returns the cut.
double checked_cut(const partition_graph& g, const std::vector<std::uint8_t>& part,
                   double fraction) {
  EXPECT_EQ(part.size(), boost::num_vertices(g));
  const auto w = pdd::part_weights(g, part);
  EXPECT_GT(std::count(part.begin(), part.end(), 0), 0);
  EXPECT_GT(std::count(part.begin(), part.end(), 1), 0);
  EXPECT_LE(std::max(w[0], w[1]), fraction * (w[0] + w[1]) * (1 + 1e-12));
  return pdd::cut_weight(g, part);
}

TYPED_TEST(Partitioner, TwoCliquesCutTheLightBridge) {
  const partition_graph g = two_cliques(8, 0.1);
  const auto part = TypeParam{}.bisect(g, {});
  EXPECT_DOUBLE_EQ(checked_cut(g, part, 0.55), 0.1);
  for (std::size_t v = 1; v < 8; ++v)
    EXPECT_EQ(part[v], part[0]);
  EXPECT_NE(part[8], part[0]);
}

TYPED_TEST(Partitioner, PathCutsOneMiddleEdge) {
  for (const std::size_t n : {13, 20, 101, 1000}) {
    const partition_graph g = path_graph(n);
    EXPECT_EQ(checked_cut(g, TypeParam{}.bisect(g, {}), 0.55), 1.0) << "n = " << n;
  }
}

TYPED_TEST(Partitioner, RingCutsTwoEdges) {
  for (const std::size_t n : {13, 64, 500}) {
    const partition_graph g = ring_graph(n);
    EXPECT_EQ(checked_cut(g, TypeParam{}.bisect(g, {}), 0.55), 2.0) << "n = " << n;
  }
}

TYPED_TEST(Partitioner, GridCutsAStraightLine) {
  const partition_graph g = grid_graph(8, 8);
  for (const double f : {0.5, 0.55}) {
    const auto part = TypeParam{}.bisect(g, {.max_part_fraction = f});
    EXPECT_EQ(checked_cut(g, part, f), 8.0) << "fraction " << f;
  }
  const partition_graph wide = grid_graph(30, 10); // optimum: cut across the long side, 10
  EXPECT_EQ(checked_cut(wide, TypeParam{}.bisect(wide, {}), 0.55), 10.0);
}

// Two 6-cliques joined by the chain 5 -0.5- 6 -0.3- 7 -0.7- 8 -0.4- 9 of light vertices:
// every chain cut is balanced, and the unique optimum cuts the 0.3 edge.
TYPED_TEST(Partitioner, WeightedDumbbellHasTheUniqueOptimum) {
  partition_graph g = with_vertices(15);
  for (std::size_t c : {0, 9})
    for (std::size_t i = 0; i < 6; ++i)
      for (std::size_t j = i + 1; j < 6; ++j)
        add(g, c + i, c + j, 2.0);
  for (std::size_t v : {6, 7, 8})
    g[v].weight = 0.01;
  add(g, 5, 6, 0.5), add(g, 6, 7, 0.3), add(g, 7, 8, 0.7), add(g, 8, 9, 0.4);
  const auto part = TypeParam{}.bisect(g, {});
  EXPECT_DOUBLE_EQ(checked_cut(g, part, 0.55), 0.3);
  for (std::size_t v = 0; v < 15; ++v)
    EXPECT_EQ(part[v] == part[0], v <= 6) << v;
}

TYPED_TEST(Partitioner, ParallelEdgesAddAndSelfLoopsVanish) {
  // Path of 20; the balanced cuts are edges (8,9) 1.2, (9,10) 3 x 0.5 and (10,11) 0.6 + 0.5.
  partition_graph g = with_vertices(20);
  for (std::size_t v = 0; v + 1 < 20; ++v)
    if (v < 8 || v > 10) add(g, v, v + 1, 1.0);
  add(g, 8, 9, 1.2);
  for (int i = 0; i < 3; ++i)
    add(g, 9, 10, 0.5);
  add(g, 10, 11, 0.6), add(g, 10, 11, 0.5);
  add(g, 5, 5, 100.0), add(g, 10, 10, 100.0);
  const auto part = TypeParam{}.bisect(g, {});
  EXPECT_NEAR(checked_cut(g, part, 0.55), 1.1, 1e-12);
  EXPECT_NE(part[10], part[11]);
}

TYPED_TEST(Partitioner, BalanceHoldsOnRandomGraphs) {
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    const partition_graph g = random_holey_grid(seed);
    for (const double f : {0.505, 0.52, 0.6, 0.8}) {
      const auto part = TypeParam{}.bisect(g, {.max_part_fraction = f, .seed = seed});
      const auto w = pdd::part_weights(g, part);
      EXPECT_LE(std::max(w[0], w[1]), f * (w[0] + w[1]) * (1 + 1e-12)) << seed << " " << f;
    }
  }
}

// Uneven shares (MADD's splits into an odd number of subdomains): part p weighs at most
// 2 max_part_fraction times its share, on random graphs, for either part the smaller.
TYPED_TEST(Partitioner, UnevenSharesHoldOnRandomGraphs) {
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    const partition_graph g = random_holey_grid(seed);
    for (const double share : {1.0 / 3.0, 0.4, 0.6, 2.0 / 3.0}) {
      const pdd::bisection_options o{
          .max_part_fraction = 0.52, .seed = seed, .target_fraction = share};
      const auto w = pdd::part_weights(g, TypeParam{}.bisect(g, o));
      const double total = w[0] + w[1], bound = 2.0 * 0.52 * (1 + 1e-12);
      EXPECT_LE(w[0], bound * share * total) << seed << " " << share;
      EXPECT_LE(w[1], bound * (1.0 - share) * total) << seed << " " << share;
    }
  }
  const partition_graph g = grid_graph(12, 12);
  for (const double bad : {0.0, 1.0, -0.2, std::numeric_limits<double>::quiet_NaN()})
    EXPECT_THROW(TypeParam{}.bisect(g, {.target_fraction = bad}), pdd::decomposition_error) << bad;
}

TYPED_TEST(Partitioner, SameSeedSameBisection) {
  for (std::uint64_t seed = 0; seed < 10; ++seed) {
    const partition_graph g = random_holey_grid(100 + seed);
    const pdd::bisection_options o{.max_part_fraction = 0.55, .seed = seed};
    const TypeParam p{};
    EXPECT_EQ(p.bisect(g, o), p.bisect(g, o));
    EXPECT_EQ(p.bisect(g, o), TypeParam{}.bisect(partition_graph(g), o));
  }
}

TYPED_TEST(Partitioner, ConcurrentCallsGiveTheSequentialResults) {
  std::vector<partition_graph> graphs;
  for (std::uint64_t s = 0; s < 8; ++s)
    graphs.push_back(s % 2 ? random_holey_grid(s) : madd_like_graph(150, 0.3, s));
  const TypeParam p{};
  std::vector<std::vector<std::uint8_t>> expected;
  for (std::size_t i = 0; i < graphs.size(); ++i)
    expected.push_back(p.bisect(graphs[i], {.seed = i}));
  std::vector<std::vector<std::vector<std::uint8_t>>> got(4);
  std::vector<std::thread> threads;
  for (std::size_t t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      got[t].resize(graphs.size());
      for (std::size_t k = 0; k < 3 * graphs.size(); ++k) {
        const std::size_t i = (k + 3 * t) % graphs.size();
        got[t][i] = p.bisect(graphs[i], {.seed = i});
      }
    });
  for (std::thread& th : threads)
    th.join();
  for (std::size_t t = 0; t < 4; ++t)
    EXPECT_EQ(got[t], expected) << "thread " << t;
}

TYPED_TEST(Partitioner, TinyGraphs) {
  const TypeParam p{};
  EXPECT_TRUE(p.bisect(partition_graph(0), {}).empty());
  EXPECT_EQ(p.bisect(with_vertices(1), {}), std::vector<std::uint8_t>{0});
  EXPECT_EQ(p.bisect(with_vertices(2), {}), (std::vector<std::uint8_t>{0, 1}));
  partition_graph g3 = with_vertices(3); // every split exceeds 0.55 alike: lightest cut wins
  add(g3, 0, 1, 5.0), add(g3, 1, 2, 1.0);
  EXPECT_EQ(p.bisect(g3, {}), (std::vector<std::uint8_t>{0, 0, 1}));
  // Unbalanceable: one vertex weighs 90%; the smallest excess isolates it.
  partition_graph heavy = with_vertices(3);
  heavy[1].weight = 18.0;
  add(heavy, 0, 1, 1.0), add(heavy, 1, 2, 2.0);
  EXPECT_EQ(p.bisect(heavy, {}), (std::vector<std::uint8_t>{0, 1, 0}));
}

TYPED_TEST(Partitioner, DisconnectedAndEdgelessGraphs) {
  const TypeParam p{};
  partition_graph islands = with_vertices(40); // 4 paths of 10
  for (std::size_t v = 0; v + 1 < 40; ++v)
    if (v % 10 != 9) add(islands, v, v + 1);
  EXPECT_EQ(checked_cut(islands, p.bisect(islands, {.max_part_fraction = 0.5}), 0.5), 0.0);
  const partition_graph bare = with_vertices(30);
  EXPECT_EQ(checked_cut(bare, p.bisect(bare, {.max_part_fraction = 0.5}), 0.5), 0.0);
  partition_graph zero = grid_graph(6, 6); // all weights zero: vertices count as one each
  for (std::size_t v = 0; v < 36; ++v)
    zero[v].weight = 0.0;
  for (const auto e : boost::make_iterator_range(boost::edges(zero)))
    zero[e].weight = 0.0;
  const auto part = p.bisect(zero, {.max_part_fraction = 0.5});
  EXPECT_EQ(std::count(part.begin(), part.end(), 1), 18);
}

TYPED_TEST(Partitioner, ZeroVertexAndEdgeWeights) {
  partition_graph g = grid_graph(10, 10); // odd columns weigh nothing; every third edge too
  for (std::size_t v = 0; v < 100; ++v)
    g[v].weight = v % 2 ? 0.0 : 1.0;
  std::size_t i = 0;
  for (const auto e : boost::make_iterator_range(boost::edges(g)))
    g[e].weight = i++ % 3 ? 1.0 : 0.0;
  for (const double f : {0.5, 0.55})
    checked_cut(g, TypeParam{}.bisect(g, {.max_part_fraction = f}), f);
}

TYPED_TEST(Partitioner, ExtremeWeightsNeitherOverflowNorVanish) {
  // Cliques of weight-1e15 edges joined by a 1e-15 bridge; vertex weights 1e15 and 1e-15.
  partition_graph g = two_cliques(10, 1e-15, 1e15);
  for (std::size_t v = 0; v < 20; ++v)
    g[v].weight = v % 3 == 0 ? 1e-15 : 1e15;
  g[9].weight = g[10].weight = 1e15;
  const auto part = TypeParam{}.bisect(g, {});
  EXPECT_EQ(pdd::cut_weight(g, part), 1e-15);
  // A grid whose weights alternate between 1e15 and 1e-15 stays valid and balanced.
  partition_graph grid = grid_graph(12, 12);
  for (std::size_t v = 0; v < 144; ++v)
    grid[v].weight = (v * 7) % 5 == 0 ? 1e15 : 1e-15;
  std::size_t i = 0;
  for (const auto e : boost::make_iterator_range(boost::edges(grid)))
    grid[e].weight = i++ % 3 == 0 ? 1e15 : 1e-15;
  checked_cut(grid, TypeParam{}.bisect(grid, {}), 0.55);
}

TYPED_TEST(Partitioner, BadInputThrows) {
  const TypeParam p{};
  partition_graph g = path_graph(20);
  EXPECT_THROW(p.bisect(g, {.max_part_fraction = 0.4}), pdd::decomposition_error);
  EXPECT_THROW(p.bisect(g, {.max_part_fraction = std::nan("")}), pdd::decomposition_error);
  g[3].weight = -1.0;
  EXPECT_THROW(p.bisect(g, {}), pdd::decomposition_error);
  g[3].weight = 1.0;
  boost::add_edge(4, 5, pdd::partition_edge{std::numeric_limits<double>::infinity()}, g);
  EXPECT_THROW(p.bisect(g, {}), pdd::decomposition_error);
}

TEST(MetisInput, ScalesWithoutOverflowAndKeepsPositiveWeights) {
  partition_graph g = two_cliques(6, 1e-15, 1e15);
  g[0].weight = 0.0;
  g[1].weight = 1e-300;
  g[2].weight = 1e300;
  boost::add_edge(0, 11, pdd::partition_edge{0.0}, g);
  const auto in = pdd::detail::to_metis_input<std::int32_t>(pdd::detail::to_ml_graph(g));
  ASSERT_EQ(in.xadj.size(), 13u);
  EXPECT_EQ(in.vwgt[0], 0);
  EXPECT_EQ(in.vwgt[1], 1);
  double vsum = 0, esum = 0;
  for (const auto w : in.vwgt)
    EXPECT_GE(w, 0), vsum += w;
  for (const auto w : in.adjwgt)
    EXPECT_GE(w, 1), esum += w;
  EXPECT_LE(vsum, pdd::detail::metis_weight_budget + 12);
  EXPECT_LE(esum, 2 * (pdd::detail::metis_weight_budget + 32));
  for (std::size_t v = 0; v < 12; ++v) // symmetric arcs
    for (auto k = in.xadj[v]; k < in.xadj[v + 1]; ++k) {
      const auto t = static_cast<std::size_t>(in.adjncy[k]);
      const auto back = std::find(in.adjncy.begin() + in.xadj[t],
                                  in.adjncy.begin() + in.xadj[t + 1], static_cast<std::int32_t>(v));
      ASSERT_NE(back, in.adjncy.begin() + in.xadj[t + 1]);
      EXPECT_EQ(in.adjwgt[static_cast<std::size_t>(back - in.adjncy.begin())], in.adjwgt[k]);
    }
}

TEST(DefaultPartitioner, IsAGraphPartitioner) {
  static_assert(pdd::GraphPartitioner<pdd::default_partitioner>);
#ifdef PDD_HAVE_METIS
  static_assert(std::is_same_v<pdd::default_partitioner, pdd::metis_partitioner>);
#else
  static_assert(std::is_same_v<pdd::default_partitioner, pdd::boost_partitioner>);
#endif
  const partition_graph g = grid_graph(10, 10);
  EXPECT_EQ(pdd::cut_weight(g, pdd::default_partitioner{}.bisect(g, {})), 10.0);
}

TEST(BisectionMetrics, CutAndWeights) {
  partition_graph g = path_graph(4);
  add(g, 1, 2, 0.5);
  add(g, 3, 3, 7.0);
  g[3].weight = 2.0;
  const std::vector<std::uint8_t> part{0, 0, 1, 1};
  EXPECT_EQ(pdd::cut_weight(g, part), 1.5);
  EXPECT_EQ(pdd::part_weights(g, part), (std::array<double, 2>{2.0, 3.0}));
  EXPECT_THROW(pdd::cut_weight(g, {0, 1}), pdd::decomposition_error);
  EXPECT_THROW(pdd::part_weights(g, {0, 1, 2, 0}), pdd::decomposition_error);
}

} // namespace

} // namespace partitioners_test
