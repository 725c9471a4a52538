/// \file shielded_loops.hpp
/// Implementation of pdd::shield: the input check, the loops walked with the domain on their
/// left, and the copy of a loop with its small-angle apices replaced by shield points
/// (Algorithm 8.2, steps 5-12).
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/errors.hpp>
#include <pdd/geometry/loops.hpp>
#include <pdd/shielding/detail/plan.hpp>
#include <pdd/shielding/shield_triangle.hpp>
#include <pdd/shielding/shielded_domain.hpp>

#include <algorithm>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

namespace pdd::detail {

/// Throws if an input segment carries pdd::shield_marker, which marks shield edges.
inline void reject_shield_marker(const pslg& g) {
  for (std::size_t s = 0; s < g.segments.size(); ++s)
    if (g.segments[s].marker == shield_marker)
      throw geometry_error("segment " + std::to_string(s) +
                               " carries the marker reserved for shield edges (INT_MIN + 1)",
                           {s});
}

/// The loops of a domain, each walked with the domain on its left: vertices[k][i] is followed
/// by segment segments[k][i].
struct oriented_loops {
  std::vector<std::vector<index_t>> vertices, segments;
};

/// The loops of lt, reversed where the domain lies on their right.
inline oriented_loops domain_on_left_loops(const loops_with_triangulation& lt) {
  oriented_loops out;
  for (const polygon_loop& l : lt.structure.loops) {
    std::vector<index_t> v = l.vertices, s = l.segments;
    if (!l.domain_on_left()) {
      // reverse: vertex i keeps its place relative to its segments
      std::reverse(v.begin(), v.end());
      std::reverse(s.begin(), s.end());
      std::rotate(s.begin(), s.begin() + 1, s.end());
    }
    out.vertices.push_back(std::move(v));
    out.segments.push_back(std::move(s));
  }
  return out;
}

/// The marker of PSLG vertex v (0 when g has no vertex markers).
inline int vertex_marker_of(const pslg& g, index_t v) {
  return v < g.vertex_markers.size() ? g.vertex_markers[v] : 0;
}

/// Appends loop k of `loops` to out.domain (vertices and segments), replacing each apex i with
/// dist[i] > 0 by its shield points and recording its shielded triangle (Algorithm 8.2, steps
/// 5-12). pts: the loop's points, theta: its small angles.
inline void append_shielded_loop(const pslg& g, const oriented_loops& loops, std::size_t k,
                                 const std::vector<point>& pts, const std::vector<double>& theta,
                                 shielded_domain& out) {
  const auto& loop = loops.vertices[k];
  const std::size_t n = loop.size();
  const std::vector<double> dist = shield_distances(pts, theta, out.l, loop);
  const auto marker = [&](std::size_t i) { return g.segments[loops.segments[k][i % n]].marker; };
  const auto first = static_cast<index_t>(out.domain.vertices.size());
  std::vector<int> edge_marker; // marker of the segment leaving each new vertex
  for (std::size_t i = 0; i < n; ++i) {
    if (dist[i] == 0.0) {
      out.domain.add_vertex(pts[i], vertex_marker_of(g, loop[i]));
      edge_marker.push_back(marker(i));
      continue;
    }
    const point a = pts[i], prev = pts[(i + n - 1) % n], next = pts[(i + 1) % n];
    const int m_prev = marker(i + n - 1), m_next = marker(i);
    shield_triangle t;
    t.apex = a;
    t.apex_marker = vertex_marker_of(g, loop[i]);
    t.c = shield_point(a, prev, dist[i]);
    t.b = shield_point(a, next, dist[i]);
    t.marker_ab = m_next;
    t.marker_ac = m_prev;
    t.angle_deg = theta[i];
    t.apex_vertex = loop[i];
    t.c_vertex = out.domain.add_vertex(t.c, m_prev);
    edge_marker.push_back(shield_marker);
    t.b_vertex = out.domain.add_vertex(t.b, m_next);
    edge_marker.push_back(m_next);
    out.triangles.push_back(t);
  }
  const auto count = static_cast<index_t>(out.domain.vertices.size()) - first;
  for (index_t i = 0; i < count; ++i) {
    const index_t s = out.domain.add_segment(first + i, first + (i + 1) % count, edge_marker[i]);
    if (edge_marker[i] == shield_marker) out.shield_segments.push_back(s);
  }
}

} // namespace pdd::detail
