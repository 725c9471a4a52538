/// \file bisection_metrics.hpp
/// pdd::cut_weight and pdd::part_weights: the two quantities a GraphPartitioner trades off (in
/// MADD, the total length of the separators and the areas of the two subdomains, dissertation
/// 3.5: "the ratio of the cut cost to the subgraph weight").
#pragma once

#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/errors.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace pdd {

namespace detail {
/// \throws decomposition_error unless part has one entry, 0 or 1, per vertex of g.
inline void check_bisection_vector(const partition_graph& g, const std::vector<std::uint8_t>& part,
                                   const char* who) {
  if (part.size() != boost::num_vertices(g))
    throw decomposition_error(std::string(who) + ": bisection has " + std::to_string(part.size()) +
                              " entries for a graph of " + std::to_string(boost::num_vertices(g)) +
                              " vertices");
  for (std::size_t v = 0; v < part.size(); ++v)
    if (part[v] > 1)
      throw decomposition_error(std::string(who) + ": vertex " + std::to_string(v) +
                                " is in part " + std::to_string(part[v]) + " (expected 0 or 1)");
}
} // namespace detail

/// Total weight of the edges whose ends lie in different parts (every parallel edge counts; self
/// loops never do). \throws decomposition_error unless part has a 0/1 entry per vertex.
/// Complexity O(n + m).
inline double cut_weight(const partition_graph& g, const std::vector<std::uint8_t>& part) {
  detail::check_bisection_vector(g, part, "cut_weight");
  double cut = 0.0;
  for (const auto e : boost::make_iterator_range(boost::edges(g)))
    if (part[boost::source(e, g)] != part[boost::target(e, g)]) cut += g[e].weight;
  return cut;
}

/// Total vertex weight of part 0 and of part 1. \throws decomposition_error unless part has a
/// 0/1 entry per vertex. Complexity O(n).
inline std::array<double, 2> part_weights(const partition_graph& g,
                                          const std::vector<std::uint8_t>& part) {
  detail::check_bisection_vector(g, part, "part_weights");
  std::array<double, 2> w{0.0, 0.0};
  for (std::size_t v = 0; v < part.size(); ++v)
    w[part[v]] += g[v].weight;
  return w;
}

} // namespace pdd
