/// \file graph_partitioner.hpp
/// The GraphPartitioner concept and the graph type it works on.
///
/// A GraphPartitioner bisects a vertex- and edge-weighted undirected graph, minimising the
/// weight of the cut edges under a balance bound.
///
/// Requirements: for `const P p`, `const pdd::partition_graph g` and
/// `const pdd::bisection_options o`, `p.bisect(g, o)` returns a std::vector<std::uint8_t> of
/// size num_vertices(g) with values 0 or 1 (the part of each vertex).
/// Semantics: both parts are non-empty when g has at least two vertices; the result is a
/// deterministic function of (g, o); part 0 weighs at most 2 o.max_part_fraction
/// o.target_fraction of the total and part 1 at most 2 o.max_part_fraction (1 -
/// o.target_fraction) of it when that is achievable (a best effort otherwise): for even shares
/// (target_fraction 0.5, the default) the heavier part weighs at most o.max_part_fraction. Parts
/// need not be connected: the library repairs disconnected parts (pdd::connected_bisection,
/// dissertation 5.1), the partitioner does not have to. Thread-safety: MADD bisects several regions
/// at once, so `bisect` may be called concurrently on different graphs; a model must be reentrant
/// or serialise itself (pdd::metis_partitioner does), and its result must not depend on timing.
/// Models: pdd::metis_partitioner (default when METIS is found, partition/metis.hpp),
/// pdd::boost_partitioner (partition/boost_partitioner.hpp); pdd::default_partitioner names
/// the default (partition/default_partitioner.hpp).
#pragma once

#include <boost/graph/adjacency_list.hpp>

#include <concepts>
#include <cstdint>
#include <vector>

namespace pdd {

/// Vertex property of a partition_graph: its weight (an area in MADD), >= 0.
struct partition_vertex {
  /// The vertex's weight, >= 0 (0: weightless, the default).
  double weight = 0.0;
};
/// Edge property of a partition_graph: its weight (a separator length in MADD), >= 0.
struct partition_edge {
  /// The edge's weight, the cost of cutting it, >= 0 (0: free to cut, the default).
  double weight = 0.0;
};

/// The graph every GraphPartitioner bisects (parallel edges are allowed; their weights add).
using partition_graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS,
                                              partition_vertex, partition_edge>;

/// Options of one bisection.
struct bisection_options {
  /// Largest fraction of the total vertex weight that the heavier part may take at even shares;
  /// in general each part may take 2 max_part_fraction times its share. In [0.5, 1].
  double max_part_fraction = 0.55;
  /// Seed of any randomised step (the result is deterministic for a given seed).
  std::uint64_t seed = 1;
  /// Part 0's share of the total vertex weight (part 1's is the rest), in (0, 1): MADD asks for
  /// a third when a region is to become three subdomains, one of them part 0's.
  double target_fraction = 0.5;
};

template <class P>
concept GraphPartitioner = requires(const P& p, const partition_graph& g,
                                    const bisection_options& o) {
  { p.bisect(g, o) } -> std::same_as<std::vector<std::uint8_t>>;
};

} // namespace pdd
