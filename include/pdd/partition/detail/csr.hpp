/// \file csr.hpp
/// Implementation detail of the partitioners: the compact working graph (Boost's
/// compressed_sparse_row_graph storing both directions of every undirected edge, parallel edges
/// merged, self loops dropped), its construction from a pdd::partition_graph with input
/// validation, the (imbalance, cut) score every partitioner minimises, and seeded randomness
/// that gives the same stream on every standard library.
#pragma once

#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/errors.hpp>

#include <boost/graph/compressed_sparse_row_graph.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace pdd::detail {

struct ml_vertex {
  double weight = 0.0;
};
struct ml_edge {
  double weight = 0.0;
};

/// Symmetric CSR graph: arc (u, v) exists iff arc (v, u) does, with the same weight; no self
/// loops, no parallel arcs.
using ml_graph = boost::compressed_sparse_row_graph<boost::directedS, ml_vertex, ml_edge>;

/// One undirected edge (or one arc) of an edge list.
struct weighted_arc {
  std::size_t u = 0;
  std::size_t v = 0;
  double w = 0.0;
};

/// Builds an ml_graph on n vertices from arcs given in both directions (u != v). Arcs with the
/// same (u, v) are merged, their weights added in input order. O((n + m) log m).
inline ml_graph make_ml_graph(std::size_t n, std::vector<weighted_arc> arcs,
                              const std::vector<double>& vertex_weights) {
  std::stable_sort(arcs.begin(), arcs.end(), [](const weighted_arc& a, const weighted_arc& b) {
    return a.u != b.u ? a.u < b.u : a.v < b.v;
  });
  std::vector<std::pair<std::size_t, std::size_t>> ends;
  std::vector<ml_edge> props;
  ends.reserve(arcs.size());
  props.reserve(arcs.size());
  for (const weighted_arc& a : arcs) {
    if (!ends.empty() && ends.back() == std::pair{a.u, a.v}) {
      props.back().weight += a.w;
    } else {
      ends.emplace_back(a.u, a.v);
      props.push_back(ml_edge{a.w});
    }
  }
  ml_graph g(boost::edges_are_sorted, ends.begin(), ends.end(), props.begin(), n);
  for (std::size_t v = 0; v < n; ++v)
    g[v].weight = vertex_weights[v];
  return g;
}

/// Throws decomposition_error unless 0.5 <= o.max_part_fraction <= 1 and 0 < o.target_fraction
/// < 1.
inline void check_bisection_options(const bisection_options& o) {
  if (!(o.max_part_fraction >= 0.5 && o.max_part_fraction <= 1.0))
    throw decomposition_error("bisection_options::max_part_fraction must lie in [0.5, 1], got " +
                              std::to_string(o.max_part_fraction));
  if (!(o.target_fraction > 0.0 && o.target_fraction < 1.0))
    throw decomposition_error("bisection_options::target_fraction must lie in (0, 1), got " +
                              std::to_string(o.target_fraction));
}

inline void check_weight(double w, const std::string& what) {
  if (!(std::isfinite(w) && w >= 0.0))
    throw decomposition_error("partition_graph: " + what + " has weight " + std::to_string(w) +
                              "; weights must be finite and >= 0");
}

/// The working graph of g: validated weights, parallel edges merged, self loops dropped. When
/// every vertex weighs zero, every vertex weighs one instead (any split is balanced by weight
/// then; counting vertices gives the meaningful balance).
/// \throws decomposition_error naming the vertex or edge whose weight is negative, NaN or
/// infinite, or when the total vertex weight overflows.
inline ml_graph to_ml_graph(const partition_graph& g) {
  const std::size_t n = boost::num_vertices(g);
  std::vector<double> vw(n);
  double total = 0.0;
  for (std::size_t v = 0; v < n; ++v) {
    check_weight(g[v].weight, "vertex " + std::to_string(v));
    vw[v] = g[v].weight;
    total += vw[v];
  }
  if (!std::isfinite(total))
    throw decomposition_error("partition_graph: the total vertex weight overflows a double");
  if (total == 0.0) std::fill(vw.begin(), vw.end(), 1.0);
  std::vector<weighted_arc> arcs;
  arcs.reserve(2 * boost::num_edges(g));
  for (const auto e : boost::make_iterator_range(boost::edges(g))) {
    const std::size_t u = boost::source(e, g), v = boost::target(e, g);
    check_weight(g[e].weight, "edge (" + std::to_string(u) + ", " + std::to_string(v) + ")");
    if (u == v) continue;
    arcs.push_back({u, v, g[e].weight});
    arcs.push_back({v, u, g[e].weight});
  }
  return make_ml_graph(n, std::move(arcs), vw);
}

inline double total_vertex_weight(const ml_graph& g) {
  double t = 0.0;
  for (std::size_t v = 0; v < boost::num_vertices(g); ++v)
    t += g[v].weight;
  return t;
}

/// Quality of a bisection: first the weight by which the heavier part exceeds the bound, then
/// the cut weight. Smaller is better, compared lexicographically.
struct bisection_score {
  double excess = 0.0;
  double cut = 0.0;
  friend bool operator<(const bisection_score& a, const bisection_score& b) {
    return a.excess != b.excess ? a.excess < b.excess : a.cut < b.cut;
  }
};

/// The most each part of a bisection may weigh: part p at most 2 max_part_fraction times its
/// share of the total (target_fraction for part 0, the rest for part 1); for even shares,
/// max_part_fraction of the total each.
using part_limits = std::array<double, 2>;

/// The part_limits of o for a graph of total vertex weight `total`.
inline part_limits part_weight_limits(const bisection_options& o, double total) {
  const double bound = 2.0 * o.max_part_fraction * total;
  return {bound * o.target_fraction, bound * (1.0 - o.target_fraction)};
}

/// The weight part 1 is meant to take (its share of `total`), from its limits.
inline double part1_target(const part_limits& limits, double total) {
  return total * limits[1] / (limits[0] + limits[1]);
}

/// By how much the parts of weights w exceed their limits (the larger excess; 0 if none does).
inline double balance_excess(const std::array<double, 2>& w, const part_limits& limits) {
  return std::max({0.0, w[0] - limits[0], w[1] - limits[1]});
}

inline std::array<double, 2> ml_part_weights(const ml_graph& g,
                                             const std::vector<std::uint8_t>& part) {
  std::array<double, 2> w{0.0, 0.0};
  for (std::size_t v = 0; v < boost::num_vertices(g); ++v)
    w[part[v]] += g[v].weight;
  return w;
}

inline double ml_cut(const ml_graph& g, const std::vector<std::uint8_t>& part) {
  double cut = 0.0;
  for (const auto e : boost::make_iterator_range(boost::edges(g))) {
    const std::size_t u = boost::source(e, g), v = boost::target(e, g);
    if (u < v && part[u] != part[v]) cut += g[e].weight;
  }
  return cut;
}

inline bisection_score score_bisection(const ml_graph& g, const std::vector<std::uint8_t>& part,
                                       const part_limits& limits) {
  return {balance_excess(ml_part_weights(g, part), limits), ml_cut(g, part)};
}

/// SplitMix64 mix of a seed and a stream number: independent generator seeds per stream.
inline std::uint64_t mix_seed(std::uint64_t seed, std::uint64_t stream) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (stream + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

/// A uniform-enough integer in [0, n) from mt19937_64, whose output the standard fixes (unlike
/// std::uniform_int_distribution and std::shuffle, which differ between libraries).
inline std::size_t random_below(std::mt19937_64& rng, std::size_t n) {
  return static_cast<std::size_t>(rng() % static_cast<std::uint64_t>(n));
}

/// A random permutation of 0..n-1 (Fisher-Yates), the same on every platform for a given rng.
inline std::vector<std::size_t> random_permutation(std::size_t n, std::mt19937_64& rng) {
  std::vector<std::size_t> perm(n);
  for (std::size_t i = 0; i < n; ++i)
    perm[i] = i;
  for (std::size_t i = n; i > 1; --i)
    std::swap(perm[i - 1], perm[random_below(rng, i)]);
  return perm;
}

} // namespace pdd::detail
