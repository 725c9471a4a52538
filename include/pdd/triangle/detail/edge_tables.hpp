/// \file edge_tables.hpp
/// Implementation of Triangle's switches e and v on a mesh: every edge once with its boundary
/// marker (.edge), and the Voronoi diagram dual to the mesh (.v.node, .v.edge).
#pragma once

#include <pdd/core/kernel.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/triangle/detail/mesh_tables.hpp>
#include <pdd/triangle/triangulation.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace pdd::triangle::detail {

/// The edges of the mesh (see triangulation::edges) and, when `voronoi` is given, its dual.
/// `nb` is pdd::triangle_neighbors(m). Complexity O(triangles) expected.
inline std::vector<mesh_edge> list_edges(const triangle_mesh& m,
                                         const std::vector<std::array<long long, 3>>& nb,
                                         voronoi_diagram* voronoi) {
  std::unordered_map<std::uint64_t, int> segment_marker;
  segment_marker.reserve(m.segments.size());
  for (const mesh_edge& s : m.segments)
    segment_marker.emplace(edge_key(s.a, s.b), s.marker);
  std::vector<mesh_edge> edges;
  edges.reserve(m.triangles.size() * 3 / 2 + 2);
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (std::size_t i = 0; i < 3; ++i) {
      const long long across = nb[t][i];
      if (across >= 0 && static_cast<std::size_t>(across) < t) continue;
      const index_t a = m.triangles[t][(i + 1) % 3], b = m.triangles[t][(i + 2) % 3];
      const auto s = segment_marker.find(edge_key(a, b));
      const int marker = s != segment_marker.end() && s->second != 0 ? s->second : across < 0;
      edges.push_back({a, b, marker});
      if (!voronoi) continue;
      const point pa = m.vertices[a], pb = m.vertices[b];
      voronoi->edges.push_back({static_cast<long long>(t), across < 0 ? -1 : across});
      voronoi->directions.push_back(across < 0 ? point{pb.y - pa.y, pa.x - pb.x} : point{});
    }
  return edges;
}

/// The Voronoi vertices: the circumcentre of every triangle (CGAL's construction).
inline std::vector<point> circumcentres(const triangle_mesh& m) {
  std::vector<point> out;
  out.reserve(m.triangles.size());
  for (const auto& t : m.triangles) {
    const auto p = [&m](index_t v) { return epick::Point_2(m.vertices[v].x, m.vertices[v].y); };
    const epick::Point_2 c = CGAL::circumcenter(p(t[0]), p(t[1]), p(t[2]));
    out.push_back({c.x(), c.y()});
  }
  return out;
}

} // namespace pdd::triangle::detail
