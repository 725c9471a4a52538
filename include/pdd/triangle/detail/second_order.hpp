/// \file second_order.hpp
/// Implementation of pdd::triangle::triangulate with o2: the extra nodes of six-node
/// (subparametric quadratic) triangles, as Triangle's highorder() makes them.
#pragma once

#include <pdd/core/triangle_mesh.hpp>
#include <pdd/triangle/detail/mesh_tables.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace pdd::triangle::detail {

/// Adds a node at the middle of every edge of m (0.5 (a + b), as Triangle computes it) after
/// its vertices, one per edge, shared by the edge's two triangles; returns per triangle t the
/// nodes in the middle of the edges opposite its corners 0, 1 and 2 (Triangle's nodes 4, 5 and
/// 6). A node's marker is the segment's marker on an input segment (m.segments), 1 on another
/// boundary edge, 0 inside (Triangle's rule). `nb`: the neighbour table
/// (pdd::triangle_neighbors: the triangle across from corner i, -1 on the boundary). Nodes are
/// numbered triangle by triangle, corner by corner, where the edge is met first.
/// The `width` values per vertex in `per_vertex` (vertex attributes) get the nodes' too, the
/// mean of the edge's ends (Triangle's rule).
/// Complexity O(triangles + segments).
inline std::vector<std::array<index_t, 3>>
add_second_order_nodes(triangle_mesh& m, const std::vector<std::array<long long, 3>>& nb,
                       std::vector<double>* per_vertex = nullptr, std::size_t width = 0) {
  std::unordered_map<std::uint64_t, int> segment_marker;
  for (const mesh_edge& e : m.segments)
    segment_marker.emplace(edge_key(e.a, e.b), e.marker);
  m.vertex_markers.resize(m.vertices.size(), 0);
  std::unordered_map<std::uint64_t, index_t> node_of_edge;
  node_of_edge.reserve(3 * m.triangles.size() / 2 + 1);
  std::vector<std::array<index_t, 3>> nodes(m.triangles.size());
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const index_t a = m.triangles[t][(i + 1) % 3], b = m.triangles[t][(i + 2) % 3];
      const auto [it, added] =
          node_of_edge.try_emplace(edge_key(a, b), static_cast<index_t>(m.vertices.size()));
      nodes[t][i] = it->second;
      if (!added) continue;
      const point p = m.vertices[a], q = m.vertices[b];
      m.vertices.push_back({0.5 * (p.x + q.x), 0.5 * (p.y + q.y)});
      const auto s = segment_marker.find(edge_key(a, b));
      m.vertex_markers.push_back(s != segment_marker.end() ? s->second : nb[t][i] < 0 ? 1 : 0);
      if (per_vertex)
        for (std::size_t k = 0; k < width; ++k)
          per_vertex->push_back(0.5 *
                                ((*per_vertex)[a * width + k] + (*per_vertex)[b * width + k]));
    }
  return nodes;
}

} // namespace pdd::triangle::detail
