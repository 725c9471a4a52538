/// \file initial.hpp
/// Implementation detail of pdd::boost_partitioner: the initial bisection of the coarsest
/// graph, by breadth-first and greedy graph growing from a pseudo-peripheral vertex and from
/// random vertices (Karypis and Kumar 1998, section 3.2, "GGP" and "GGGP"), each refined by
/// FM, the best kept.
#pragma once

#include <pdd/partition/detail/csr.hpp>
#include <pdd/partition/detail/exact.hpp>
#include <pdd/partition/detail/fm.hpp>
#include <pdd/partition/detail/traversal.hpp>

#include <cstddef>
#include <cstdint>
#include <random>
#include <set>
#include <utility>
#include <vector>

namespace pdd::detail {

/// Part 1 := the shortest prefix of the BFS order from seed that reaches target weight (at
/// least one vertex, at most n - 1).
inline std::vector<std::uint8_t> bfs_bisection(const ml_graph& g, std::size_t seed, double target) {
  const std::size_t n = boost::num_vertices(g);
  std::vector<std::uint8_t> part(n, 0);
  double w1 = 0.0;
  const std::vector<std::size_t> order = breadth_first_order(g, seed, true);
  for (std::size_t i = 0; i + 1 < n && (i == 0 || w1 < target); ++i) {
    part[order[i]] = 1;
    w1 += g[order[i]].weight;
  }
  return part;
}

/// The state of grow_bisection: part 1 so far, its weight, and the frontier ordered by
/// priority = (weight to part 1) - (weight to part 0).
struct growing_part {
  const ml_graph& g;
  std::vector<std::uint8_t> part;
  std::vector<double> priority;
  std::vector<char> queued;
  std::set<std::pair<double, std::size_t>, fm_gain_order> frontier;
  double w1 = 0.0;
  std::size_t count = 0;

  explicit growing_part(const ml_graph& graph)
      : g(graph), part(boost::num_vertices(graph), 0), priority(part.size(), 0.0),
        queued(part.size(), 0) {
    for (std::size_t v = 0; v < part.size(); ++v)
      for (const auto e : boost::make_iterator_range(boost::out_edges(v, g)))
        priority[v] -= g[e].weight;
  }

  /// Moves v to part 1 and updates its neighbours' priorities.
  void add(std::size_t v) {
    if (queued[v]) frontier.erase({priority[v], v});
    part[v] = 1;
    w1 += g[v].weight;
    ++count;
    for (const auto e : boost::make_iterator_range(boost::out_edges(v, g))) {
      const std::size_t t = boost::target(e, g);
      if (part[t]) continue;
      if (queued[t]) frontier.erase({priority[t], t});
      priority[t] += 2.0 * g[e].weight;
      queued[t] = 1;
      frontier.insert({priority[t], t});
    }
  }
};

/// Greedy graph growing: part 1 starts as {seed} and repeatedly takes the frontier vertex whose
/// move raises the cut least, skipping vertices that would push it over its limit, until it
/// reaches target. A disconnected graph continues from its lowest vertex outside part 1.
inline std::vector<std::uint8_t> grow_bisection(const ml_graph& g, std::size_t seed, double target,
                                                const part_limits& limits) {
  const std::size_t n = boost::num_vertices(g);
  growing_part gp(g);
  std::size_t next_outside = 0;
  gp.add(seed);
  while (gp.w1 < target && gp.count + 1 < n) {
    std::size_t pick = n;
    for (const auto& [p, v] : gp.frontier)
      if (gp.w1 + g[v].weight <= limits[1]) {
        pick = v;
        break;
      }
    while (gp.frontier.empty() && pick == n && next_outside < n)
      if (!gp.part[next_outside++]) pick = next_outside - 1;
    if (pick == n) break;
    gp.add(pick);
  }
  return std::move(gp.part);
}

/// The best FM-refined bisection of (small) g among `tries` grown ones: try 0 grows by BFS
/// from a pseudo-peripheral vertex, try 1 greedily from it, the others greedily from random
/// vertices. Graphs of at most exact_bisection_max_vertices are solved exactly.
inline std::vector<std::uint8_t> initial_bisection(const ml_graph& g, const part_limits& limits,
                                                   int tries, int fm_passes, std::mt19937_64& rng) {
  const std::size_t n = boost::num_vertices(g);
  if (n <= exact_bisection_max_vertices) return exact_bisection(g, limits);
  const double target = part1_target(limits, total_vertex_weight(g));
  const std::size_t peripheral = pseudo_peripheral_vertex(g, random_below(rng, n));
  std::vector<std::uint8_t> best;
  bisection_score best_score{};
  for (int t = 0; t < tries; ++t) {
    std::vector<std::uint8_t> part =
        t == 0 ? bfs_bisection(g, peripheral, target)
               : grow_bisection(g, t == 1 ? peripheral : random_below(rng, n), target, limits);
    const bisection_score s = fm_refine(g, part, limits, fm_passes);
    if (best.empty() || s < best_score) {
      best = std::move(part);
      best_score = s;
    }
  }
  return best;
}

} // namespace pdd::detail
