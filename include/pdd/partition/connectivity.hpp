/// \file connectivity.hpp
/// pdd::connected_bisection: the library-side guarantee that a MADD bisection has two connected
/// parts, whatever the GraphPartitioner returns (dissertation 5.1: METIS "does not always
/// produce connected components, while the MADD method requires a graph partition into two
/// connected subgraphs. A routine was implemented that identifies these cases and restores the
/// connectivity"; Lemma 6 of 3.5 needs connected subgraphs for connected subdomains).
#pragma once

#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/errors.hpp>
#include <pdd/partition/bisection_metrics.hpp>
#include <pdd/partition/detail/connected_refine.hpp>
#include <pdd/partition/detail/csr.hpp>
#include <pdd/partition/detail/repair.hpp>
#include <pdd/partition/detail/repaired_bisection.hpp>

#include <boost/graph/connected_components.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace pdd {

/// Bisects the connected graph g with the partitioner p and returns a bisection whose two parts
/// are non-empty and each induce a connected subgraph. When p's bisection is already such, it
/// is returned unchanged. Otherwise the candidates are: p's bisection repaired by letting each
/// part keep its heaviest connected component and moving the stray components to the other
/// part (which lowers the cut: a stray component's edges all lead to the other part), in both
/// orders (part 0 first, part 1 first; skipped when p left a part empty); and three connected
/// growths up to part 1's share of the weight (BFS from a pseudo-peripheral vertex, greedy graph
/// growing from it and from the far end of its BFS), repaired likewise. Each candidate is then
/// rebalanced and its cut lowered greedily by moving boundary vertices that are not
/// articulation points of their part (both parts stay connected). The candidate with the
/// smallest excess over the parts' limits (bisection_options), then the smallest cut, wins
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
  return detail::repaired_bisection(g, raw, weight, detail::part_weight_limits(o, total));
}

} // namespace pdd
