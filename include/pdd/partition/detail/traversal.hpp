/// \file traversal.hpp
/// Implementation detail of the partitioners and of pdd::connected_bisection: breadth-first
/// orders and pseudo-peripheral vertices, over Boost.Graph's breadth_first_visit.
#pragma once

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/breadth_first_search.hpp>
#include <boost/pending/queue.hpp>
#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <vector>

namespace pdd::detail {

/// BFS event visitor that appends each discovered vertex to a list.
struct discovery_recorder {
  using event_filter = boost::on_discover_vertex;
  std::vector<std::size_t>* order;
  template <class Vertex, class Graph>
  void operator()(Vertex v, const Graph&) const {
    order->push_back(v);
  }
};

/// The vertices in breadth-first discovery order from source (boost::breadth_first_visit); with
/// all_components, the other components follow, each from its lowest unvisited vertex.
/// Works on any Boost.Graph IncidenceGraph with vertex_index 0..n-1 (ml_graph, partition_graph).
template <class Graph>
std::vector<std::size_t> breadth_first_order(const Graph& g, std::size_t source,
                                             bool all_components) {
  const std::size_t n = boost::num_vertices(g);
  std::vector<std::size_t> order;
  order.reserve(n);
  std::vector<boost::default_color_type> color(n, boost::white_color);
  const auto color_map =
      boost::make_iterator_property_map(color.begin(), boost::get(boost::vertex_index, g));
  const auto visitor = boost::make_bfs_visitor(discovery_recorder{&order});
  boost::queue<std::size_t> buffer;
  boost::breadth_first_visit(g, source, buffer, visitor, color_map);
  for (std::size_t v = 0; all_components && v < n; ++v)
    if (color[v] == boost::white_color)
      boost::breadth_first_visit(g, v, buffer, visitor, color_map);
  return order;
}

/// A vertex of large eccentricity in start's component: repeatedly the last vertex a BFS
/// discovers (George and Liu's pseudo-peripheral heuristic, three sweeps).
template <class Graph>
std::size_t pseudo_peripheral_vertex(const Graph& g, std::size_t start) {
  std::size_t v = start;
  for (int sweep = 0; sweep < 3; ++sweep)
    v = breadth_first_order(g, v, false).back();
  return v;
}

} // namespace pdd::detail
