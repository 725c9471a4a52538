/// \file shield.hpp
/// pdd::shield: the shielding of small input angles (< 60 deg) of dissertation 8.1
/// (Algorithms 8.1 and 8.2, Lemma 23, Theorem 24) for a pslg domain.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/errors.hpp>
#include <pdd/geometry/lfs.hpp>
#include <pdd/geometry/loops.hpp>
#include <pdd/shielding/detail/plan.hpp>
#include <pdd/shielding/shield_triangle.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

namespace pdd {

/// A domain with its small angles shielded: D' = D - T_D (Algorithm 8.2, steps 5-12).
struct shielded_domain {
  /// D': the loops of D with every small-angle apex a replaced by the shield points b', c' and
  /// the shield edge b'c' (marker pdd::shield_marker). Vertices in loop order (the loops of
  /// pdd::find_loops, each walked with the domain on its left); holes and regions copied.
  /// When D has no angle below 60 deg, this is D itself, unchanged.
  pslg domain;
  /// T_D: the shielded triangles, counter-clockwise (apex, b, c).
  std::vector<shield_triangle> triangles;
  /// Per triangle: the index of its shield edge in domain.segments.
  std::vector<index_t> shield_segments;
  /// l of line 5 of Algorithm 8.2 (infinity when there is no small angle).
  double l = std::numeric_limits<double>::infinity();
  /// lfs_min(D) (Definition 7); infinity when there is no small angle (not computed).
  double lfs_min = std::numeric_limits<double>::infinity();
};

namespace detail {

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

} // namespace detail
/// Shields every angle theta < 60 deg of the domain of g (Algorithm 8.2 for one subdomain):
/// l = min over the small angles of {(1 + 2 sin(theta/2)) sqrt(2 A sin theta), sqrt(A / sqrt 2),
/// lfs_min(g)} (eq. 8.6, A = area_bound; without an area bound l = lfs_min, Algorithm 8.1);
/// b', c' on the two segments at the apex a at |ab'| = |ac'| = l / (2 sin(theta/2)
/// (cos(theta/2) + sin theta)) (eq. 8.1). By Lemma 23 and Theorem 24, D' has no angle below
/// 60 deg, lfs_min(D') > l / sqrt 3, shield edges are never split by Ruppert-type refinement
/// and the shielded triangles have area <= A and ratio 1 / (2 sin theta).
/// \pre g is valid (pdd::validate): closed loops. area_bound > 0 (infinity: none).
/// \throws pdd::geometry_error as find_loops(), or naming the vertices when two shield points
/// would not fit on a segment (cannot happen for a valid domain, Lemma 23 (ii), (iv)).
/// Complexity O(n log n) expected (loops and lfs_min). Thread-safe.
inline shielded_domain shield(const pslg& g, double area_bound) {
  detail::reject_shield_marker(g);
  detail::loops_with_triangulation lt;
  detail::find_loops_into(g, lt);
  shielded_domain out;
  const detail::oriented_loops loops = detail::domain_on_left_loops(lt);
  const std::size_t nl = loops.vertices.size();
  std::vector<std::vector<point>> pts(nl);
  bool any = false;
  std::vector<std::vector<double>> theta(nl);
  for (std::size_t k = 0; k < nl; ++k) {
    for (const index_t v : loops.vertices[k])
      pts[k].push_back(g.vertices[v]);
    theta[k] = detail::shield_angles(pts[k], std::vector<char>(pts[k].size(), 1));
    any = any || std::any_of(theta[k].begin(), theta[k].end(), [](double t) { return t > 0.0; });
  }
  if (!any) {
    out.domain = g;
    return out;
  }
  out.lfs_min = lfs_min(g, lt);
  out.l = detail::shield_length(theta, out.lfs_min, area_bound);
  for (std::size_t k = 0; k < nl; ++k)
    detail::append_shielded_loop(g, loops, k, pts[k], theta[k], out);
  out.domain.holes = g.holes;
  out.domain.regions = g.regions;
  return out;
}

} // namespace pdd
