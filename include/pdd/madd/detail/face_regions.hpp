/// \file face_regions.hpp
/// Implementation detail of MADD on a general PSLG (one not of closed loops, issue 13): its
/// faces (pdd::domain_faces, by the PSLG's rule) as the first regions, each a polygon with
/// holes whose loops are walked along the segments around it. A segment between two faces of
/// the domain (an internal constraint) is then an edge of both regions: MADD keeps their
/// vertices conforming (apply_edge_splits) and assemble_decomposition makes it an interface,
/// so the decoupling path splits it like a separator.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_measures.hpp>
#include <pdd/geometry/domain_faces.hpp>
#include <pdd/madd/detail/region.hpp>

#include <algorithm>
#include <cstddef>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace pdd::detail {

/// The faces of a general PSLG as MADD regions, or why it cannot be decoupled.
struct face_region_set {
  std::vector<madd_region> regions; ///< by face id; empty when `refusal` is set
  /// Empty when every face is a polygon with holes whose corners on internal constraints are
  /// >= 60 deg; else what stops decoupling (names the segment or vertex ids).
  std::string refusal;
};

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

/// The boundary half-edges of every face (a triangle edge whose twin lies in another face or
/// outside the domain), sorted by face then tail. `refusal` names a segment with the same face
/// on both sides (a dangling segment). Complexity O(T log T) for T domain triangles.
inline std::vector<face_half_edge>
face_boundaries(const pslg& g, const std::vector<domain_triangle>& tris,
                const std::vector<std::tuple<index_t, index_t, index_t>>& segments,
                std::string& refusal) {
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
      if (s != no_index && refusal.empty())
        refusal = "segment " + std::to_string(s) + " (" + vertex_name(g, h.a) + " to " +
                  vertex_name(g, h.b) +
                  ") has the same face on both sides (a dangling segment): the decoupled "
                  "pipeline needs every segment in the domain to bound a face";
      continue;
    }
    out.push_back(h);
  }
  std::sort(out.begin(), out.end(), [](const face_half_edge& x, const face_half_edge& y) {
    return std::tie(x.face, x.a) < std::tie(y.face, y.a);
  });
  return out;
}

/// Checks that no vertex with the domain around it lies on no segment (an isolated vertex).
inline void check_isolated_vertices(const pslg& g, const domain_faces& faces,
                                    std::string& refusal) {
  std::vector<char> on_segment(g.vertices.size(), 0);
  for (const segment& s : g.segments)
    on_segment[s.a] = on_segment[s.b] = 1;
  for (index_t v = 0; v < g.vertices.size() && refusal.empty(); ++v)
    if (!on_segment[v] && faces.touches_domain(v))
      refusal = vertex_name(g, v) +
                " lies on no segment (an isolated vertex): the decoupled pipeline needs every "
                "vertex in the domain on the boundary of a face";
}

/// Walks the boundary half-edges of one face (edges[first, last), sorted by tail) into
/// loops. False (with `refusal`) when a vertex starts two of them (the face touches itself
/// there, a pinch vertex).
inline bool walk_face_loops(const pslg& g, const std::vector<face_half_edge>& edges,
                            std::size_t first, std::size_t last,
                            std::vector<std::vector<index_t>>& loops, std::string& refusal) {
  for (std::size_t i = first; i + 1 < last; ++i)
    if (edges[i].a == edges[i + 1].a) {
      refusal = vertex_name(g, edges[i].a) +
                " is visited twice by the boundary of one face (loops that touch there): the "
                "decoupled pipeline needs every face to be a polygon with holes";
      return false;
    }
  std::vector<char> used(last - first, 0);
  auto next_of = [&](index_t v) {
    const auto it = std::lower_bound(edges.begin() + static_cast<std::ptrdiff_t>(first),
                                     edges.begin() + static_cast<std::ptrdiff_t>(last), v,
                                     [](const face_half_edge& e, index_t x) { return e.a < x; });
    return static_cast<std::size_t>(it - edges.begin()) - first;
  };
  for (std::size_t s = 0; s < used.size(); ++s) {
    if (used[s]) continue;
    std::vector<index_t> loop;
    for (std::size_t k = s; !used[k]; k = next_of(edges[first + k].b)) {
      used[k] = 1;
      loop.push_back(edges[first + k].a);
    }
    loops.push_back(std::move(loop));
  }
  return true;
}

/// Refusal text when the corner of `loop` at position i (a face corner) is < 60 deg and one of
/// its sides is an internal constraint (a segment with another face of the domain beyond it),
/// else empty.
inline std::string small_constraint_corner(const pslg& g, const std::vector<index_t>& loop,
                                           std::size_t i,
                                           const std::vector<face_half_edge>& boundary_by_edge) {
  const std::size_t n = loop.size();
  const index_t prev = loop[(i + n - 1) % n], v = loop[i], next = loop[(i + 1) % n];
  const double angle = interior_angle_deg(g.vertices[prev], g.vertices[v], g.vertices[next]);
  if (angle >= 60.0) return {};
  auto internal = [&](index_t a, index_t b) { // the twin b -> a bounds another face
    return std::binary_search(boundary_by_edge.begin(), boundary_by_edge.end(),
                              face_half_edge{b, a, 0});
  };
  if (!internal(prev, v) && !internal(v, next)) return {};
  return "the corner of " + std::to_string(angle) + " deg at " + vertex_name(g, v) +
         " between an internal constraint and another segment is below 60 deg: the decoupled "
         "pipeline shields small angles on the domain boundary only";
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

/// The faces of the domain of g (pdd::domain_faces by g.rule) as MADD regions, in face order,
/// or the first reason (dangling segment, isolated vertex, pinch vertex, constraint corner
/// below 60 deg) why the decoupled pipeline cannot take g. Each region's loops run along PSLG
/// segments, tagged external with the segment id and marker.
/// \throws pdd::geometry_error as pdd::domain_faces. Complexity O(n log n) expected.
inline face_region_set face_regions(const pslg& g) {
  face_region_set out;
  const domain_faces faces(g);
  const auto segs = segment_lookup(g);
  const std::vector<face_half_edge> edges =
      face_boundaries(g, faces.triangles(), segs, out.refusal);
  check_isolated_vertices(g, faces, out.refusal);
  if (!out.refusal.empty()) return out;
  std::vector<face_half_edge> by_edge = edges;
  std::sort(by_edge.begin(), by_edge.end());
  for (std::size_t first = 0; first < edges.size();) {
    std::size_t last = first;
    while (last < edges.size() && edges[last].face == edges[first].face)
      ++last;
    std::vector<std::vector<index_t>> loops;
    if (!walk_face_loops(g, edges, first, last, loops, out.refusal)) break;
    for (const auto& loop : loops)
      for (std::size_t i = 0; i < loop.size() && out.refusal.empty(); ++i)
        out.refusal = small_constraint_corner(g, loop, i, by_edge);
    if (!out.refusal.empty()) break;
    out.regions.push_back(face_region(g, loops, segs));
    first = last;
  }
  if (!out.refusal.empty()) out.regions.clear();
  return out;
}

} // namespace pdd::detail
