/// \file face_walk.hpp
/// Implementation detail of MADD on a general PSLG (issue 13): the boundary half-edges of each
/// face of the domain (pdd::domain_faces' triangles, a face id per triangle: a face, or a
/// group of faces joined into one region), the features inside a face (segments with the face
/// on both sides, isolated vertices), and the walk of a face's boundary into loops, weakly
/// simple where the face touches itself at a pinch vertex, as a MADD region.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/core/ray_order.hpp>
#include <pdd/core/triangle_measures.hpp>
#include <pdd/geometry/domain_faces.hpp>
#include <pdd/madd/detail/region.hpp>

#include <algorithm>
#include <cstddef>
#include <string>
#include <tuple>
#include <vector>

namespace pdd::detail {

/// A directed edge of a domain triangle (the triangle on its left) and the triangle's face.
struct face_half_edge {
  index_t a, b, face;
  friend bool operator<(const face_half_edge& x, const face_half_edge& y) {
    return std::tie(x.a, x.b) < std::tie(y.a, y.b);
  }
};

/// The segment id of every undirected PSLG edge (smaller id first), sorted for lookup.
inline std::vector<std::tuple<index_t, index_t, index_t>> segment_lookup(const pslg& g) {
  std::vector<std::tuple<index_t, index_t, index_t>> out;
  for (index_t s = 0; s < g.segments.size(); ++s)
    out.emplace_back(std::min(g.segments[s].a, g.segments[s].b),
                     std::max(g.segments[s].a, g.segments[s].b), s);
  std::sort(out.begin(), out.end());
  return out;
}

/// The segment of edge ab, no_index when ab is not a PSLG segment.
inline index_t segment_of(const std::vector<std::tuple<index_t, index_t, index_t>>& lookup,
                          index_t a, index_t b) {
  const auto key = std::make_tuple(std::min(a, b), std::max(a, b), index_t{0});
  const auto it = std::lower_bound(lookup.begin(), lookup.end(), key);
  if (it == lookup.end() || std::get<0>(*it) != std::get<0>(key) ||
      std::get<1>(*it) != std::get<1>(key))
    return no_index;
  return std::get<2>(*it);
}

/// Where `v` is, for messages: "vertex 7 (0.5, 1)".
inline std::string vertex_name(const pslg& g, index_t v) {
  return "vertex " + std::to_string(v) + " " + to_string(g.vertices[v]);
}

/// A segment with the same face on both sides (dangling, or joining two points of that
/// face's boundary) as a feature of that face.
inline madd_feature segment_feature(const pslg& g, index_t s) {
  const segment& sg = g.segments[s];
  auto marker = [&](index_t v) { return v < g.vertex_markers.size() ? g.vertex_markers[v] : 0; };
  return {g.vertices[sg.a], g.vertices[sg.b], marker(sg.a), marker(sg.b), s, sg.marker};
}

/// The boundary half-edges of every face (a triangle edge whose twin lies in another face or
/// outside the domain), sorted by face then tail. A segment with the same face on both sides
/// goes to features[face] instead. Complexity O(T log T) for T domain triangles.
inline std::vector<face_half_edge>
face_boundaries(const pslg& g, const std::vector<domain_triangle>& tris,
                const std::vector<std::tuple<index_t, index_t, index_t>>& segments,
                std::vector<std::vector<madd_feature>>& features) {
  std::vector<face_half_edge> half;
  for (const domain_triangle& t : tris)
    for (int i = 0; i < 3; ++i)
      half.push_back({t.vertices[i], t.vertices[(i + 1) % 3], t.face});
  std::sort(half.begin(), half.end());
  std::vector<face_half_edge> out;
  for (const face_half_edge& h : half) {
    const auto twin = std::lower_bound(half.begin(), half.end(), face_half_edge{h.b, h.a, 0});
    const bool inside = twin != half.end() && twin->a == h.b && twin->b == h.a;
    if (inside && twin->face == h.face) {
      const index_t s = segment_of(segments, h.a, h.b);
      if (s != no_index && h.a < h.b) features[h.face].push_back(segment_feature(g, s));
      continue;
    }
    out.push_back(h);
  }
  std::sort(out.begin(), out.end(), [](const face_half_edge& x, const face_half_edge& y) {
    return std::tie(x.face, x.a) < std::tie(y.face, y.a);
  });
  return out;
}

/// Adds every vertex on no segment with the domain around it (an isolated vertex) to the
/// features of its face.
inline void add_isolated_vertices(const pslg& g, const std::vector<domain_triangle>& tris,
                                  std::vector<std::vector<madd_feature>>& features) {
  std::vector<char> on_segment(g.vertices.size(), 0);
  for (const segment& s : g.segments)
    on_segment[s.a] = on_segment[s.b] = 1;
  std::vector<index_t> face_of(g.vertices.size(), no_index);
  for (const domain_triangle& t : tris)
    for (const index_t v : t.vertices)
      if (!on_segment[v]) face_of[v] = t.face;
  for (index_t v = 0; v < g.vertices.size(); ++v)
    if (face_of[v] != no_index) {
      const int m = v < g.vertex_markers.size() ? g.vertex_markers[v] : 0;
      features[face_of[v]].push_back({g.vertices[v], g.vertices[v], m, m, no_index, 0});
    }
}

/// The boundary half-edge of the face that follows u -> v (candidates: edges[lo, hi), those
/// leaving v): the first one clockwise from v -> u, so that the face stays on the left. At a
/// pinch vertex (the face touches itself there) this takes the sector that u -> v bounds.
inline std::size_t next_boundary_edge(const pslg& g, const std::vector<face_half_edge>& edges,
                                      std::size_t lo, std::size_t hi, index_t u) {
  std::size_t best = lo;
  const point pv = g.vertices[edges[lo].a], pu = g.vertices[u];
  for (std::size_t i = lo + 1; i < hi; ++i)
    if (ray_turns_before(pv, pu, g.vertices[edges[best].b], g.vertices[edges[i].b])) best = i;
  return best;
}

/// Walks the boundary half-edges of one face (edges[first, last), sorted by tail) into
/// loops, keeping the face on the left. Where the face touches itself (a pinch vertex: loops
/// of the PSLG that meet at one vertex) a loop visits that vertex once per sector of the face
/// there, so the loops are weakly simple: MADD and the subdomains keep each visit apart.
inline void walk_face_loops(const pslg& g, const std::vector<face_half_edge>& edges,
                            std::size_t first, std::size_t last,
                            std::vector<std::vector<index_t>>& loops) {
  std::vector<char> used(last - first, 0);
  const auto begin = edges.begin() + static_cast<std::ptrdiff_t>(first);
  const auto end = edges.begin() + static_cast<std::ptrdiff_t>(last);
  auto next_of = [&](std::size_t k) {
    const index_t v = edges[first + k].b;
    const auto by_tail = [](const face_half_edge& e, index_t x) { return e.a < x; };
    const auto lo = std::lower_bound(begin, end, v, by_tail);
    auto hi = lo;
    while (hi != end && hi->a == v)
      ++hi;
    PDD_ASSERT(lo != hi);
    return next_boundary_edge(g, edges, static_cast<std::size_t>(lo - edges.begin()),
                              static_cast<std::size_t>(hi - edges.begin()), edges[first + k].a) -
           first;
  };
  for (std::size_t s = 0; s < used.size(); ++s) {
    if (used[s]) continue;
    std::vector<index_t> loop;
    for (std::size_t k = s; !used[k]; k = next_of(k)) {
      used[k] = 1;
      loop.push_back(edges[first + k].a);
    }
    loops.push_back(std::move(loop));
  }
}

/// One face's loops as a MADD region: the counter-clockwise loop first, then the holes.
inline madd_region face_region(const pslg& g, const std::vector<std::vector<index_t>>& loops,
                               const std::vector<std::tuple<index_t, index_t, index_t>>& segs) {
  madd_region r;
  for (const auto& loop : loops) {
    madd_loop l;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const index_t v = loop[i], w = loop[(i + 1) % loop.size()];
      const index_t s = segment_of(segs, v, w);
      PDD_ASSERT(s != no_index);
      l.points.push_back(g.vertices[v]);
      l.markers.push_back(v < g.vertex_markers.size() ? g.vertex_markers[v] : 0);
      l.tags.push_back(madd_edge_tag{true, s, g.segments[s].marker});
    }
    const bool outer = polygon_signed_area(l.points) > 0.0;
    if (outer)
      r.loops.insert(r.loops.begin(), std::move(l));
    else
      r.loops.push_back(std::move(l));
  }
  r.area = region_area(r);
  return r;
}

} // namespace pdd::detail
