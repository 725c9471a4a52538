/// \file repair.hpp
/// Implementation detail of pdd::connected_bisection (dissertation 5.1: "a routine ... that
/// identifies these cases and restores the connectivity"): components of each part, moving
/// stray components across, and connected growths as further candidates.
#pragma once

#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/partition/detail/csr.hpp>
#include <pdd/partition/detail/initial.hpp>
#include <pdd/partition/detail/traversal.hpp>

#include <boost/graph/connected_components.hpp>
#include <boost/graph/filtered_graph.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pdd::detail {

/// Vertex filter of a filtered_graph: the vertices of one part.
struct part_filter {
  const std::vector<std::uint8_t>* part = nullptr;
  std::uint8_t side = 0;
  bool operator()(std::size_t v) const { return (*part)[v] == side; }
};

/// Connected components of the subgraph that part `side` induces (boost::connected_components
/// on a filtered_graph): comp[v] for v in that part, numbered in order of their lowest vertex.
/// Returns their number. O(n + m).
inline std::size_t part_components(const partition_graph& g, const std::vector<std::uint8_t>& part,
                                   std::uint8_t side, std::vector<std::size_t>& comp) {
  const boost::filtered_graph<partition_graph, boost::keep_all, part_filter> induced(
      g, boost::keep_all{}, part_filter{&part, side});
  comp.assign(boost::num_vertices(g), 0);
  return boost::connected_components(
      induced, boost::make_iterator_property_map(comp.begin(), boost::get(boost::vertex_index, g)));
}

/// True when both parts are non-empty and each induces a connected subgraph.
inline bool is_connected_bisection(const partition_graph& g,
                                   const std::vector<std::uint8_t>& part) {
  std::vector<std::size_t> comp;
  return part_components(g, part, 0, comp) == 1 && part_components(g, part, 1, comp) == 1;
}

/// Keeps the heaviest component of part `side` (ties: more vertices, then lowest vertex) and
/// moves every other component of it to the other part. weight[v] are the effective weights.
inline void keep_heaviest_component(const partition_graph& g, std::vector<std::uint8_t>& part,
                                    std::uint8_t side, const std::vector<double>& weight) {
  std::vector<std::size_t> comp;
  const std::size_t count = part_components(g, part, side, comp);
  if (count <= 1) return;
  std::vector<double> cw(count, 0.0);
  std::vector<std::size_t> cn(count, 0);
  for (std::size_t v = 0; v < part.size(); ++v)
    if (part[v] == side) cw[comp[v]] += weight[v], ++cn[comp[v]];
  std::size_t keep = 0;
  for (std::size_t c = 1; c < count; ++c)
    if (cw[c] > cw[keep] || (cw[c] == cw[keep] && cn[c] > cn[keep])) keep = c;
  for (std::size_t v = 0; v < part.size(); ++v)
    if (part[v] == side && comp[v] != keep) part[v] = static_cast<std::uint8_t>(1 - side);
}

/// Repairs a bisection of a connected graph with two non-empty parts: first part `first` keeps
/// its heaviest component (the strays join the other part, each adjacent to it), then the other
/// part does; afterwards both parts are connected and non-empty (every stray of the second step
/// is adjacent only to the first part, which is connected by then).
inline std::vector<std::uint8_t> repair_bisection(const partition_graph& g,
                                                  std::vector<std::uint8_t> part,
                                                  std::uint8_t first,
                                                  const std::vector<double>& weight) {
  keep_heaviest_component(g, part, first, weight);
  keep_heaviest_component(g, part, static_cast<std::uint8_t>(1 - first), weight);
  return part;
}

/// Connected growths of part 1 up to its share of the weight (the grown part is connected; the rest
/// need not be, so callers repair it): the BFS prefix from a pseudo-peripheral vertex a, and greedy
/// graph growing (least cut increase first) from a and from the last vertex of a's BFS.
/// \pre g connected, n >= 2; weight are the effective vertex weights. O((n + m) log n).
inline std::vector<std::vector<std::uint8_t>> connected_growths(const partition_graph& g,
                                                                const std::vector<double>& weight,
                                                                const part_limits& limits) {
  const std::size_t n = boost::num_vertices(g);
  double total = 0.0, grown = 0.0;
  for (const double w : weight)
    total += w;
  const std::size_t a = pseudo_peripheral_vertex(g, 0);
  const std::vector<std::size_t> order = breadth_first_order(g, a, false);
  std::vector<std::vector<std::uint8_t>> growths(1, std::vector<std::uint8_t>(n, 0));
  for (std::size_t i = 0; i + 1 < n && (i == 0 || grown < part1_target(limits, total)); ++i) {
    growths[0][order[i]] = 1;
    grown += weight[order[i]];
  }
  const ml_graph mg = to_ml_graph(g); // same effective weights
  for (const std::size_t seed : {a, order.back()})
    growths.push_back(grow_bisection(mg, seed, part1_target(limits, total), limits));
  return growths;
}

} // namespace pdd::detail
