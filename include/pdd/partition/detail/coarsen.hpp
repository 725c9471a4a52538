/// \file coarsen.hpp
/// Implementation detail of pdd::boost_partitioner: the coarsening phase of multilevel
/// bisection, heavy-edge matching and contraction (B. Hendrickson, R. Leland, "A multilevel
/// algorithm for partitioning graphs", 1995; G. Karypis, V. Kumar, "A fast and high quality
/// multilevel scheme for partitioning irregular graphs", SIAM J. Sci. Comput. 20(1), 1998).
#pragma once

#include <pdd/partition/detail/csr.hpp>

#include <cstddef>
#include <random>
#include <vector>

namespace pdd::detail {

/// One coarsening step: the coarse graph and, for every vertex of the finer graph, its coarse
/// vertex.
struct coarse_level {
  ml_graph graph;
  std::vector<std::size_t> fine_to_coarse;
};

/// Heavy-edge matching: visits the vertices in a random order and matches each unmatched one
/// with the unmatched neighbour across its heaviest edge (ties: lighter pair, then lower
/// index), never forming a vertex heavier than max_vertex_weight. match[v] is v's partner, or
/// v when unmatched. O(n + m).
inline std::vector<std::size_t> heavy_edge_matching(const ml_graph& g, std::mt19937_64& rng,
                                                    double max_vertex_weight) {
  const std::size_t n = boost::num_vertices(g);
  constexpr std::size_t none = static_cast<std::size_t>(-1);
  std::vector<std::size_t> match(n, none);
  for (const std::size_t v : random_permutation(n, rng)) {
    if (match[v] != none) continue;
    std::size_t best = v;
    double best_w = -1.0, best_pair = 0.0;
    for (const auto e : boost::make_iterator_range(boost::out_edges(v, g))) {
      const std::size_t t = boost::target(e, g);
      const double pair = g[v].weight + g[t].weight;
      if (match[t] != none || pair > max_vertex_weight) continue;
      const double w = g[e].weight;
      if (w > best_w || (w == best_w && (pair < best_pair || (pair == best_pair && t < best)))) {
        best = t;
        best_w = w;
        best_pair = pair;
      }
    }
    match[v] = best;
    match[best] = v;
  }
  return match;
}

/// Contracts every matched pair into one coarse vertex (numbered in order of the pair's lower
/// vertex); parallel coarse arcs are merged, arcs inside a pair vanish. O((n + m) log m).
inline coarse_level contract(const ml_graph& g, const std::vector<std::size_t>& match) {
  const std::size_t n = boost::num_vertices(g);
  constexpr std::size_t none = static_cast<std::size_t>(-1);
  std::vector<std::size_t> cmap(n, none), members; // members: the pairs, two entries each
  for (std::size_t v = 0; v < n; ++v) {
    if (cmap[v] != none) continue;
    cmap[v] = cmap[match[v]] = members.size() / 2;
    members.push_back(v);
    members.push_back(match[v]);
  }
  const std::size_t nc = members.size() / 2;
  std::vector<double> vw(nc, 0.0), acc(nc, 0.0);
  std::vector<char> seen(nc, 0);
  std::vector<std::size_t> touched;
  std::vector<weighted_arc> arcs;
  for (std::size_t c = 0; c < nc; ++c) {
    const std::size_t a = members[2 * c], b = members[2 * c + 1];
    vw[c] = a == b ? g[a].weight : g[a].weight + g[b].weight;
    for (std::size_t k = 0; k < (a == b ? 1U : 2U); ++k) {
      const std::size_t v = k == 0 ? a : b;
      for (const auto e : boost::make_iterator_range(boost::out_edges(v, g))) {
        const std::size_t t = cmap[boost::target(e, g)];
        if (t == c) continue;
        if (!seen[t]) seen[t] = 1, touched.push_back(t);
        acc[t] += g[e].weight;
      }
    }
    for (const std::size_t t : touched) {
      if (c < t) { // each coarse edge summed once, so both its arcs carry the same weight
        arcs.push_back({c, t, acc[t]});
        arcs.push_back({t, c, acc[t]});
      }
      acc[t] = 0.0;
      seen[t] = 0;
    }
    touched.clear();
  }
  return {make_ml_graph(nc, std::move(arcs), vw), std::move(cmap)};
}

} // namespace pdd::detail
