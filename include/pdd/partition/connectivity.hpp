/// \file connectivity.hpp
/// pdd::connected_bisection: the library-side guarantee that a MADD bisection has two connected
/// parts, whatever the GraphPartitioner returns (dissertation 5.1: METIS "does not always
/// produce connected components, while the MADD method requires a graph partition into two
/// connected subgraphs. A routine was implemented that identifies these cases and restores the
/// connectivity"; Lemma 6 of 3.5 needs connected subgraphs for connected subdomains).
#pragma once

#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/partition/detail/connected_refine.hpp>
#include <pdd/partition/detail/csr.hpp>
#include <pdd/partition/detail/repair.hpp>
#include <pdd/errors.hpp>
#include <pdd/partition/bisection_metrics.hpp>

#include <boost/graph/connected_components.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
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
/// The best connected candidate derived from the disconnected bisection raw (see
/// pdd::connected_bisection). \pre g connected, n >= 2.
inline std::vector<std::uint8_t> repaired_bisection(const partition_graph& g,
                                                    const std::vector<std::uint8_t>& raw,
                                                    const std::vector<double>& weight,
                                                    double max_weight) {
  const std::size_t n = raw.size();
  const auto repaired = [&](std::vector<std::uint8_t> part, std::uint8_t first) {
    part = repair_bisection(g, std::move(part), first, weight);
    connected_refine(g, part, weight, max_weight, n);
    return part;
  };
  const std::size_t ones = static_cast<std::size_t>(std::count(raw.begin(), raw.end(), 1));
  std::vector<std::vector<std::uint8_t>> candidates;
  if (ones != 0 && ones != n) {
    candidates.push_back(repaired(raw, 0));
    candidates.push_back(repaired(raw, 1));
  }
  for (std::vector<std::uint8_t>& growth : connected_growths(g, weight, max_weight))
    candidates.push_back(repaired(std::move(growth), 1));
  std::size_t best = 0;
  bisection_score best_score = score_of(g, candidates[0], weight, max_weight);
  for (std::size_t i = 1; i < candidates.size(); ++i) {
    const bisection_score s = score_of(g, candidates[i], weight, max_weight);
    if (s < best_score) best = i, best_score = s;
  }
  PDD_ASSERT(is_connected_bisection(g, candidates[best]));
  return candidates[best];
}
} // namespace detail

/// Bisects the connected graph g with the partitioner p and returns a bisection whose two parts
/// are non-empty and each induce a connected subgraph. When p's bisection is already such, it
/// is returned unchanged. Otherwise the candidates are: p's bisection repaired by letting each
/// part keep its heaviest connected component and moving the stray components to the other
/// part (which lowers the cut: a stray component's edges all lead to the other part), in both
/// orders (part 0 first, part 1 first; skipped when p left a part empty); and three connected
/// growths up to half the weight (BFS from a pseudo-peripheral vertex, greedy graph growing
/// from it and from the far end of its BFS), repaired likewise. Each candidate is then
/// rebalanced and its cut lowered greedily by moving boundary vertices that are not
/// articulation points of their part (both parts stay connected). The candidate with the
/// smallest excess over o.max_part_fraction of the total weight, then the smallest cut, wins
/// (the first on ties). All-zero vertex weights count as ones.
/// \tparam P a GraphPartitioner.
/// \pre g is connected and has at least two vertices.
/// \throws decomposition_error if g has fewer than two vertices or is not connected, if a
/// weight is negative or not finite, if o.max_part_fraction is outside [0.5, 1], or if p
/// returns a vector of the wrong size or with entries other than 0 and 1; whatever p throws.
/// Complexity O(n + m) plus p's bisection when p's bisection is connected; O(k (n + m)) for k
/// refinement moves otherwise (k <= n). Deterministic when p is.
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
  return detail::repaired_bisection(g, raw, weight, o.max_part_fraction * total);
}

} // namespace pdd
