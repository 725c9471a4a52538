/// \file connected_refine.hpp
/// Implementation detail of pdd::connected_bisection: greedy rebalancing and cut refinement of a
/// connected bisection that keep both parts connected. A vertex may move when it is on the
/// boundary (so it joins the other part connected) and is not an articulation point of its own
/// part (boost::articulation_points on the part's induced subgraph), so its part stays
/// connected.
#pragma once

#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/partition/detail/csr.hpp>
#include <pdd/partition/detail/repair.hpp>

#include <boost/graph/biconnected_components.hpp>
#include <boost/graph/filtered_graph.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <optional>
#include <vector>

namespace pdd::detail {

/// flags[v] = 1 when v is an articulation point of the subgraph that part `side` induces.
inline std::vector<char> part_articulation_points(const partition_graph& g,
                                                  const std::vector<std::uint8_t>& part,
                                                  std::uint8_t side) {
  const boost::filtered_graph<partition_graph, boost::keep_all, part_filter> induced(
      g, boost::keep_all{}, part_filter{&part, side});
  std::vector<std::size_t> points;
  boost::articulation_points(induced, std::back_inserter(points));
  std::vector<char> flags(part.size(), 0);
  for (const std::size_t v : points)
    flags[v] = 1;
  return flags;
}

/// The move a connected refinement step makes: while a part exceeds its limit, the
/// movable vertex whose move lowers the excess with the largest cut gain; else the movable
/// vertex with the largest positive gain whose move keeps the bisection balanced. Ties: lowest
/// vertex. O(n + m).
inline std::optional<std::size_t> connected_move(const partition_graph& g,
                                                 const std::vector<std::uint8_t>& part,
                                                 const std::vector<double>& weight,
                                                 const part_limits& limits) {
  const std::array<std::vector<char>, 2> articulation{part_articulation_points(g, part, 0),
                                                      part_articulation_points(g, part, 1)};
  std::array<double, 2> w{0.0, 0.0};
  std::array<std::size_t, 2> count{0, 0};
  for (std::size_t v = 0; v < part.size(); ++v)
    w[part[v]] += weight[v], ++count[part[v]];
  const double excess = balance_excess(w, limits);
  std::optional<std::size_t> best;
  double best_gain = 0.0;
  for (std::size_t v = 0; v < part.size(); ++v) {
    const std::uint8_t s = part[v];
    if (count[s] < 2 || articulation[s][v]) continue;
    double gain = 0.0;
    bool boundary = false;
    for (const auto e : boost::make_iterator_range(boost::out_edges(v, g))) {
      const std::size_t t = boost::target(e, g);
      if (t == v) continue;
      boundary = boundary || part[t] != s;
      gain += part[t] != s ? g[e].weight : -g[e].weight;
    }
    std::array<double, 2> after = w;
    after[s] -= weight[v];
    after[1 - s] += weight[v];
    const double excess_after = balance_excess(after, limits);
    const bool allowed = excess > 0.0 ? excess_after < excess : excess_after == 0.0 && gain > 0.0;
    if (boundary && allowed && (!best || gain > best_gain)) best = v, best_gain = gain;
  }
  return best;
}

/// Applies connected_move until none is left (at most max_moves). Both parts stay non-empty and
/// connected; the excess never grows, and once balanced the cut only falls.
/// \pre both parts non-empty and connected. O(moves (n + m)).
inline void connected_refine(const partition_graph& g, std::vector<std::uint8_t>& part,
                             const std::vector<double>& weight, const part_limits& limits,
                             std::size_t max_moves) {
  for (std::size_t moves = 0; moves < max_moves; ++moves) {
    const std::optional<std::size_t> v = connected_move(g, part, weight, limits);
    if (!v) return;
    part[*v] ^= 1U;
  }
}

} // namespace pdd::detail
