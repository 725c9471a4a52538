/// \file boundary_markers.hpp
/// Triangle's boundary markers on pdd's output (triangle.c's "Boundary Markers" section): the
/// marker of every output vertex and of every edge on an input segment, whatever path made the
/// mesh.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/triangle/detail/mesh_tables.hpp>

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace pdd::triangle::detail {

/// For every edge of m.segments, whether it lies on the boundary of the triangulation (one
/// triangle has it as a side). Only triangles with two corners on segment edges are looked up.
/// Complexity O(triangles + segments) expected.
inline std::vector<char> boundary_segment_edges(const triangle_mesh& m) {
  std::vector<char> on_segment(m.vertices.size(), 0);
  std::unordered_map<std::uint64_t, std::size_t> edge_of;
  edge_of.reserve(m.segments.size());
  for (std::size_t s = 0; s < m.segments.size(); ++s) {
    on_segment[m.segments[s].a] = on_segment[m.segments[s].b] = 1;
    edge_of.emplace(edge_key(m.segments[s].a, m.segments[s].b), s);
  }
  std::vector<int> sides(m.segments.size(), 0);
  for (const auto& t : m.triangles)
    for (int i = 0; i < 3; ++i) {
      const index_t a = t[i], b = t[(i + 1) % 3];
      if (!on_segment[a] || !on_segment[b]) continue;
      const auto it = edge_of.find(edge_key(a, b));
      if (it != edge_of.end()) ++sides[it->second];
    }
  std::vector<char> boundary(m.segments.size(), 0);
  for (std::size_t s = 0; s < sides.size(); ++s)
    boundary[s] = sides[s] == 1;
  return boundary;
}

/// Sets the markers of `m` by Triangle's rule, `in` being what was meshed (its vertices the
/// first vertices of m, in order; pass its segments only where Triangle reads them, with p):
/// - an edge on an input segment (m.segments) keeps the segment's nonzero marker, else it gets
///   1 on the boundary of the triangulation (a hole's too), else 0;
/// - a vertex keeps its nonzero input marker; else it takes the marker of a segment with a
///   nonzero marker that it lies on (an end included: the first such input segment, in input
///   order, as Triangle marks vertices when it inserts the segments; a Steiner vertex lies on
///   one segment); else 1 on the boundary of the triangulation; else 0.
/// Vertices of no triangle (outside the domain, equal ones) follow the same rule: an input
/// segment's end is marked even where the segment was eaten with a hole, as Triangle does.
/// Complexity O(triangles + vertices + segments) expected.
inline void apply_boundary_markers(triangle_mesh& m, const pslg& in) {
  std::vector<int> marker(m.vertices.size(), 0);
  for (std::size_t i = 0; i < in.vertex_markers.size() && i < marker.size(); ++i)
    marker[i] = in.vertex_markers[i];
  const auto mark = [&](index_t v, int value) {
    if (v < marker.size() && marker[v] == 0) marker[v] = value;
  };
  for (const segment& s : in.segments)
    if (s.marker != 0) {
      mark(s.a, s.marker);
      mark(s.b, s.marker);
    }
  for (const mesh_edge& e : m.segments)
    if (e.marker != 0) {
      mark(e.a, e.marker);
      mark(e.b, e.marker);
    }
  const std::vector<char> boundary = boundary_segment_edges(m);
  for (std::size_t s = 0; s < m.segments.size(); ++s)
    if (boundary[s]) {
      mesh_edge& e = m.segments[s];
      if (e.marker == 0) e.marker = 1;
      mark(e.a, 1);
      mark(e.b, 1);
    }
  m.vertex_markers = std::move(marker);
}

} // namespace pdd::triangle::detail
