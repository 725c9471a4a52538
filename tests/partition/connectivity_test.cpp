// pdd::connected_bisection on hundreds of random connected planar-ish graphs with the library's
// partitioners and with adversarial ones (disconnected or empty parts), plus the METIS/Boost
// cut-quality comparison (printed; see README.md beside this file).
#include "partition_graphs.hpp"
#include "test_support.hpp"

#include <pdd/partition/bisection_metrics.hpp>
#include <pdd/partition/boost_partitioner.hpp>
#include <pdd/partition/connectivity.hpp>
#include <pdd/partition/default_partitioner.hpp>
#include <pdd/partition/metis.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <vector>

namespace connectivity_test {
namespace {

using pdd::partition_graph;
using namespace pdd::test;

/// Adversarial partitioners: vertex parity (maximally disconnected), everything in part 0
/// (an empty part), and halves by vertex index (often disconnected on holey grids).
struct parity_partitioner {
  std::vector<std::uint8_t> bisect(const partition_graph& g, const pdd::bisection_options&) const {
    std::vector<std::uint8_t> part(boost::num_vertices(g));
    for (std::size_t v = 0; v < part.size(); ++v)
      part[v] = static_cast<std::uint8_t>(v % 2);
    return part;
  }
};
struct one_part_partitioner {
  std::vector<std::uint8_t> bisect(const partition_graph& g, const pdd::bisection_options&) const {
    return std::vector<std::uint8_t>(boost::num_vertices(g), 0);
  }
};
struct index_halves_partitioner {
  std::vector<std::uint8_t> bisect(const partition_graph& g, const pdd::bisection_options&) const {
    std::vector<std::uint8_t> part(boost::num_vertices(g));
    for (std::size_t v = 0; v < part.size(); ++v)
      part[v] = v >= part.size() / 2;
    return part;
  }
};
struct wrong_size_partitioner {
  std::vector<std::uint8_t> bisect(const partition_graph&, const pdd::bisection_options&) const {
    return {0, 1};
  }
};

// The test graphs, built once: 200 holey grids and 40 MADD-like duals (all connected).
const std::vector<partition_graph>& test_graphs() {
  static const std::vector<partition_graph> graphs = [] {
    std::vector<partition_graph> out;
    for (std::uint64_t i = 0; i < 240; ++i)
      out.push_back(i < 200 ? random_holey_grid(1000 + i)
                            : madd_like_graph(60 + 10 * (i - 200), 0.5, i));
    return out;
  }();
  return graphs;
}

struct family_result {
  int repaired = 0;   // raw bisections that were not connected
  int unbalanced = 0; // results over the balance bound
};

template <class P>
family_result check_family(const P& p, const char* name) {
  family_result r;
  for (std::uint64_t i = 0; i < 240; ++i) {
    const partition_graph& g = test_graphs()[i];
    const pdd::bisection_options o{.max_part_fraction = 0.55, .seed = i};
    const auto part = pdd::connected_bisection(g, p, o);
    EXPECT_EQ(part.size(), boost::num_vertices(g));
    EXPECT_EQ(connected_nonempty_parts(g, part), 2) << name << " graph " << i;
    if (i % 4 == 0) { // determinism
      EXPECT_EQ(pdd::connected_bisection(g, p, o), part) << name << " graph " << i;
    }
    const auto w = pdd::part_weights(g, part);
    if (std::max(w[0], w[1]) > 0.55 * (w[0] + w[1])) ++r.unbalanced;
    const auto raw = p.bisect(g, o);
    if (connected_nonempty_parts(g, raw) != 2)
      ++r.repaired;
    else
      EXPECT_EQ(raw, part) << "a connected bisection is returned unchanged";
  }
  std::printf("%-20s %3d of 240 raw bisections disconnected, %d results over the bound\n", name,
              r.repaired, r.unbalanced);
  return r;
}

TEST(ConnectedBisection, LibraryPartitionersOnRandomGraphs) {
  const family_result b = check_family(pdd::boost_partitioner{}, "boost_partitioner");
  EXPECT_GT(b.repaired, 0); // the family does exercise the repair
  EXPECT_LE(b.unbalanced, 5);
#ifdef PDD_HAVE_METIS
  const family_result m = check_family(pdd::metis_partitioner{}, "metis_partitioner");
  EXPECT_GT(m.repaired, 0);
  EXPECT_LE(m.unbalanced, 5);
#endif
}

TEST(ConnectedBisection, AdversarialPartitionersOnRandomGraphs) {
  const family_result parity = check_family(parity_partitioner{}, "parity");
  EXPECT_EQ(parity.repaired, 240);
  EXPECT_LE(parity.unbalanced, 5);
  const family_result one_part = check_family(one_part_partitioner{}, "one part");
  EXPECT_EQ(one_part.repaired, 240);
  EXPECT_LE(one_part.unbalanced, 5);
  EXPECT_GT(check_family(index_halves_partitioner{}, "index halves").repaired, 0);
}

TEST(ConnectedBisection, RepairKeepsBalanceWhenStraysAreSmall) {
  // Two cliques joined by an edge; the raw bisection puts one vertex of the left clique on the
  // right: the repair moves it back and restores the optimal, balanced cut.
  struct stray_partitioner {
    std::vector<std::uint8_t> bisect(const partition_graph& g,
                                     const pdd::bisection_options&) const {
      std::vector<std::uint8_t> part(boost::num_vertices(g), 0);
      for (std::size_t v = 8; v < part.size(); ++v)
        part[v] = 1;
      part[2] = 1;
      return part;
    }
  };
  const partition_graph g = two_cliques(8, 0.1);
  const auto part = pdd::connected_bisection(g, stray_partitioner{}, {});
  EXPECT_DOUBLE_EQ(pdd::cut_weight(g, part), 0.1);
  EXPECT_EQ(pdd::part_weights(g, part), (std::array<double, 2>{8.0, 8.0}));
}

TEST(ConnectedBisection, GrowthFallbackIsBalancedOnAPath) {
  const partition_graph g = path_graph(101);
  const auto part = pdd::connected_bisection(g, one_part_partitioner{}, {});
  EXPECT_EQ(pdd::cut_weight(g, part), 1.0);
  const auto w = pdd::part_weights(g, part);
  EXPECT_LE(std::max(w[0], w[1]), 0.55 * 101);
}

// The growth fallback grows part 1 to its share: a third of a path for part 0, connected.
TEST(ConnectedBisection, GrowthFallbackTakesUnevenShares) {
  const partition_graph g = path_graph(99);
  for (const double share : {1.0 / 3.0, 2.0 / 3.0}) {
    const auto part = pdd::connected_bisection(
        g, one_part_partitioner{}, {.max_part_fraction = 0.52, .target_fraction = share});
    EXPECT_EQ(pdd::cut_weight(g, part), 1.0) << share;
    const auto w = pdd::part_weights(g, part);
    EXPECT_LE(w[0], 1.04 * share * 99) << share;
    EXPECT_LE(w[1], 1.04 * (1.0 - share) * 99) << share;
  }
}

TEST(ConnectedBisection, SmallestGraphs) {
  partition_graph two = with_vertices(2);
  add(two, 0, 1);
  EXPECT_EQ(pdd::connected_bisection(two, pdd::boost_partitioner{}, {}),
            (std::vector<std::uint8_t>{0, 1}));
  const partition_graph three = path_graph(3);
  const auto part = pdd::connected_bisection(three, parity_partitioner{}, {});
  EXPECT_EQ(connected_nonempty_parts(three, part), 2);
}

TEST(ConnectedBisection, BadInputThrows) {
  const pdd::boost_partitioner p;
  EXPECT_THROW(pdd::connected_bisection(with_vertices(1), p, {}), pdd::decomposition_error);
  partition_graph split = path_graph(6);
  boost::remove_edge(2, 3, split);
  EXPECT_THROW(pdd::connected_bisection(split, p, {}), pdd::decomposition_error);
  EXPECT_THROW(pdd::connected_bisection(path_graph(6), wrong_size_partitioner{}, {}),
               pdd::decomposition_error);
  EXPECT_THROW(pdd::connected_bisection(path_graph(6), p, {.max_part_fraction = 1.5}),
               pdd::decomposition_error);
  partition_graph negative = path_graph(6);
  negative[2].weight = -3.0;
  EXPECT_THROW(pdd::connected_bisection(negative, parity_partitioner{}, {}),
               pdd::decomposition_error);
}

#ifdef PDD_HAVE_METIS
// Not a timing test: mean cuts of the partitioners on three families, printed for the record
// (README.md), with loose checks that the Boost partitioner and the default METIS settings
// stay competitive.
TEST(PartitionQuality, MetisAndBoostOnGridsAndRandomGraphs) {
  struct family {
    const char* name;
    partition_graph (*make)(std::uint64_t);
  };
  const family families[] = {
      {"grids 8-37 x 8-37", [](std::uint64_t s) { return grid_graph(8 + s % 30, 8 + s / 2); }},
      {"holey grids", [](std::uint64_t s) { return random_holey_grid(s); }},
      {"MADD-like duals", [](std::uint64_t s) { return madd_like_graph(200 + 25 * s, 0.3, s); }}};
  const pdd::metis_partitioner metis_default{};
  const pdd::metis_partitioner metis_rec{pdd::metis_scheme::recursive, 1};
  const pdd::metis_partitioner metis_kway1{pdd::metis_scheme::kway, 1};
  const pdd::boost_partitioner boost_default{};
  for (const family& f : families) {
    double cut[4] = {0, 0, 0, 0};
    for (std::uint64_t s = 0; s < 60; ++s) {
      const partition_graph g = f.make(s);
      const pdd::bisection_options o{.max_part_fraction = 0.55, .seed = s};
      cut[0] += pdd::cut_weight(g, metis_default.bisect(g, o));
      cut[1] += pdd::cut_weight(g, metis_rec.bisect(g, o));
      cut[2] += pdd::cut_weight(g, metis_kway1.bisect(g, o));
      cut[3] += pdd::cut_weight(g, boost_default.bisect(g, o));
    }
    std::printf("%-18s mean cut: metis kway ncuts=4 %.4f | metis recursive ncuts=1 %.4f | metis "
                "kway ncuts=1 %.4f | boost %.4f\n",
                f.name, cut[0] / 60, cut[1] / 60, cut[2] / 60, cut[3] / 60);
    EXPECT_LE(cut[3], 1.05 * cut[0]) << f.name;
    EXPECT_LE(cut[0], 1.02 * cut[1]) << f.name;
  }
}
#endif

} // namespace

} // namespace connectivity_test
