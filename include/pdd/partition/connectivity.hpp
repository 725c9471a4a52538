/// \file connectivity.hpp
/// pdd::connected_bisection: the library-side guarantee that a MADD bisection has two connected
/// parts, whatever the GraphPartitioner returns (dissertation 5.1: METIS "does not always
/// produce connected components, while the MADD method requires a graph partition into two
/// connected subgraphs. A routine was implemented that identifies these cases and restores the
/// connectivity"; Lemma 6 of 3.5 needs connected subgraphs for connected subdomains).
#pragma once

#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/detail/partition_csr.hpp>
#include <pdd/detail/partition_repair.hpp>
#include <pdd/errors.hpp>
#include <pdd/partition/bisection_metrics.hpp>

#include <boost/graph/connected_components.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pdd {

namespace detail {
/// Validated vertex weights of g for balancing (all ones when all are zero) and edge checks.
inline std::vector<double> effective_vertex_weights(const partition_graph& g) {
  std::vector<double> w(boost::num_vertices(g));
  double total = 0.0;
  for (std::size_t v = 0; v < w.size(); ++v) {
    check_weight(g[v].weight, "vertex " + std::to_string(v));
    total += w[v] = g[v].weight;
  }
  for (const auto e : boost::make_iterator_range(boost::edges(g)))
    check_weight(g[e].weight, "edge (" + std::to_string(boost::source(e, g)) + ", " +
                                  std::to_string(boost::target(e, g)) + ")");
  if (total == 0.0) w.assign(w.size(), 1.0);
  return w;
}

inline bisection_score score_of(const partition_graph& g, const std::vector<std::uint8_t>& part,
                                const std::vector<double>& weight, double max_weight) {
  std::array<double, 2> pw{0.0, 0.0};
  for (std::size_t v = 0; v < part.size(); ++v)
    pw[part[v]] += weight[v];
  return {balance_excess(pw, max_weight), cut_weight(g, part)};
}
} // namespace detail

/// Bisects the connected graph g with the partitioner p and returns a bisection whose two parts
/// are non-empty and each induce a connected subgraph. When p's bisection is already such, it
/// is returned unchanged. Otherwise each part keeps its heaviest connected component and the
/// stray components move to the other part, in both orders (part 0 first, part 1 first); if p
/// left a part empty, or both repairs exceed the balance bound, a connected growth (BFS prefix
/// from a pseudo-peripheral vertex up to half the weight, then repaired) is a third candidate.
/// The candidate with the smallest excess over o.max_part_fraction of the total weight, then
/// the smallest cut, wins (the first on ties). All-zero vertex weights count as ones.
/// \tparam P a GraphPartitioner.
/// \pre g is connected and has at least two vertices.
/// \throws decomposition_error if g has fewer than two vertices or is not connected, if a
/// weight is negative or not finite, if o.max_part_fraction is outside [0.5, 1], or if p
/// returns a vector of the wrong size or with entries other than 0 and 1; whatever p throws.
/// Complexity O(n + m) plus p's bisection. Deterministic when p is.
/// Thread-safety: reentrant when p.bisect is.
template <GraphPartitioner P>
std::vector<std::uint8_t> connected_bisection(const partition_graph& g, const P& p,
                                              const bisection_options& o) {
  const std::size_t n = boost::num_vertices(g);
  if (n < 2)
    throw decomposition_error("connected_bisection: the graph has " + std::to_string(n) +
                              " vertices; a bisection needs at least two");
  detail::check_bisection_options(o);
  const std::vector<double> weight = detail::effective_vertex_weights(g);
  std::vector<std::size_t> comp(n);
  const std::size_t components = boost::connected_components(g, comp.data());
  if (components != 1)
    throw decomposition_error(
        "connected_bisection: the graph has " + std::to_string(components) +
        " connected components (vertex " +
        std::to_string(std::find(comp.begin(), comp.end(), 1) - comp.begin()) +
        " is not reachable from vertex 0); it must be connected");
  std::vector<std::uint8_t> raw = p.bisect(g, o);
  detail::check_bisection_vector(g, raw, "connected_bisection (the partitioner's result)");
  if (detail::is_connected_bisection(g, raw)) return raw;

  double total = 0.0;
  for (const double w : weight)
    total += w;
  const double max_weight = o.max_part_fraction * total;
  const std::size_t ones = static_cast<std::size_t>(std::count(raw.begin(), raw.end(), 1));
  std::vector<std::vector<std::uint8_t>> candidates;
  if (ones != 0 && ones != n) {
    candidates.push_back(detail::repair_bisection(g, raw, 0, weight));
    candidates.push_back(detail::repair_bisection(g, raw, 1, weight));
  }
  const auto excess = [&](const std::vector<std::uint8_t>& c) {
    return detail::score_of(g, c, weight, max_weight).excess;
  };
  if (candidates.empty() || (excess(candidates[0]) > 0.0 && excess(candidates[1]) > 0.0))
    candidates.push_back(
        detail::repair_bisection(g, detail::connected_growth(g, weight), 1, weight));
  std::size_t best = 0;
  for (std::size_t i = 1; i < candidates.size(); ++i)
    if (detail::score_of(g, candidates[i], weight, max_weight) <
        detail::score_of(g, candidates[best], weight, max_weight))
      best = i;
  PDD_ASSERT(detail::is_connected_bisection(g, candidates[best]));
  return candidates[best];
}

} // namespace pdd
