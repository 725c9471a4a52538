/// \file detail/loops.hpp
/// Implementation of pdd/geometry/loops.hpp: segment incidence, loop tracing, and the
/// constrained triangulation of a PSLG whose flood fill gives loop nesting and the domain.
#pragma once

#include <pdd/core/kernel.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_measures.hpp>
#include <pdd/errors.hpp>
#include <pdd/triangulation/constrained_delaunay_2.hpp>

#include <array>
#include <cmath>
#include <cstddef>
#include <deque>
#include <string>
#include <utility>
#include <vector>

namespace pdd {

namespace detail {

inline epick::Point_2 to_cgal(const point& p) {
  return {p.x, p.y};
}

/// Per-face data of the PSLG triangulation: nesting level (number of loops enclosing the
/// face; -1 before the flood fill), the innermost loop enclosing it, a dense triangle id, and
/// the face of the arrangement it lies in (pslg_faces: triangles joined across unconstrained
/// edges; 0 is the unbounded face).
struct cdt_face_info {
  int level = -1;
  index_t owner = no_index;
  index_t id = no_index;
  index_t face = no_index;
};

/// The constrained Delaunay triangulation of a PSLG (vertex info: the PSLG vertex id);
/// constraints must not intersect or pass through a vertex.
using pslg_cdt = constrained_delaunay_2<index_t, cdt_face_info>;

/// Comma-separated list of at most `limit` ids (then ", ...").
template <class Ids>
std::string id_list(const Ids& ids, std::size_t limit = 10) {
  std::string s;
  std::size_t n = 0;
  for (auto id : ids) {
    if (n == limit) return s + ", ...";
    if (n++ > 0) s += ", ";
    s += std::to_string(id);
  }
  return s;
}

/// The segments incident to each vertex (the first two; degree counts them all).
struct segment_incidence {
  std::vector<std::array<index_t, 2>> first_two;
  std::vector<index_t> degree;
};

/// Counts incident segments per vertex.
/// \throws geometry_error if a segment index is out of range or a segment has a == b.
/// Complexity O(V + S).
inline segment_incidence incident_segments(const pslg& g) {
  const std::size_t nv = g.vertices.size();
  segment_incidence inc{std::vector<std::array<index_t, 2>>(nv, {no_index, no_index}),
                        std::vector<index_t>(nv, 0)};
  for (std::size_t s = 0; s < g.segments.size(); ++s) {
    const segment& sg = g.segments[s];
    if (sg.a >= nv || sg.b >= nv)
      throw geometry_error("segment " + std::to_string(s) + " refers to vertex " +
                               std::to_string(sg.a >= nv ? sg.a : sg.b) + " but there are only " +
                               std::to_string(nv) + " vertices",
                           {s});
    if (sg.a == sg.b)
      throw geometry_error("segment " + std::to_string(s) +
                               " has zero length (both ends are vertex " + std::to_string(sg.a) +
                               ")",
                           {s});
    for (index_t v : {sg.a, sg.b}) {
      if (inc.degree[v] < 2) inc.first_two[v][inc.degree[v]] = static_cast<index_t>(s);
      ++inc.degree[v];
    }
  }
  return inc;
}

/// Throws unless every vertex lies on exactly two segments.
/// \throws geometry_error naming the vertices (ids()) and their segments.
inline void require_degree_two(const pslg& g, const segment_incidence& inc) {
  std::vector<std::size_t> bad;
  std::string detail;
  for (std::size_t v = 0; v < inc.degree.size(); ++v) {
    if (inc.degree[v] == 0 || inc.degree[v] == 2) continue;
    if (bad.size() < 10) {
      std::vector<std::size_t> segs;
      for (std::size_t s = 0; s < g.segments.size() && segs.size() < 10; ++s)
        if (g.segments[s].a == v || g.segments[s].b == v) segs.push_back(s);
      detail += (bad.empty() ? "" : "; ") + std::string("vertex ") + std::to_string(v) + " has " +
                std::to_string(inc.degree[v]) + " incident segment" +
                (inc.degree[v] == 1 ? "" : "s") + " (segment" + (segs.size() == 1 ? " " : "s ") +
                id_list(segs) + ")";
    }
    bad.push_back(v);
  }
  if (!bad.empty())
    throw geometry_error("dangling segments and internal constraint segments are not supported "
                         "yet (every vertex must lie on exactly two segments): " +
                             detail + (bad.size() > 10 ? "; ..." : ""),
                         bad);
  for (std::size_t v = 0; v < inc.degree.size(); ++v)
    if (inc.degree[v] == 0) bad.push_back(v);
  if (!bad.empty())
    throw geometry_error("isolated vertices are not supported yet: vertex" +
                             std::string(bad.size() == 1 ? " " : "es ") + id_list(bad) +
                             (bad.size() == 1 ? " lies" : " lie") + " on no segment",
                         bad);
}

/// The other endpoint of segment s seen from vertex v.
inline index_t other_end(const pslg& g, index_t s, index_t v) {
  return g.segments[s].a == v ? g.segments[s].b : g.segments[s].a;
}

/// Shoelace area of a vertex cycle (pdd::detail::polygon_signed_area: relative to its first
/// vertex, less cancellation).
inline double shoelace_area(const pslg& g, const std::vector<index_t>& cycle) {
  return polygon_signed_area(cycle.size(), [&](std::size_t i) { return g.vertices[cycle[i]]; });
}

/// Exact orientation of a simple cycle: the turn at its lexicographically smallest vertex.
inline bool cycle_is_ccw(const pslg& g, const std::vector<index_t>& cycle) {
  std::size_t m = 0;
  for (std::size_t i = 1; i < cycle.size(); ++i)
    if (g.vertices[cycle[i]] < g.vertices[cycle[m]]) m = i;
  const std::size_t n = cycle.size();
  return CGAL::orientation(to_cgal(g.vertices[cycle[(m + n - 1) % n]]),
                           to_cgal(g.vertices[cycle[m]]),
                           to_cgal(g.vertices[cycle[(m + 1) % n]])) == CGAL::LEFT_TURN;
}

/// A PSLG's constrained triangulation with its faces labelled by the nesting flood fill.
struct loop_triangulation {
  pslg_cdt cdt;
  std::vector<pslg_cdt::Vertex_handle> vertex; ///< by PSLG vertex id
  std::vector<pslg_cdt::Face_handle> faces;    ///< finite faces by cdt_face_info::id
  std::vector<index_t> loop_of_segment;        ///< by PSLG segment id
};

/// The PSLG segment joining vertices u and v (both of degree 2), or no_index.
inline index_t segment_between(const pslg& g, const segment_incidence& inc, index_t u, index_t v) {
  for (index_t s : inc.first_two[u])
    if (s != no_index && other_end(g, s, u) == v) return s;
  return no_index;
}

/// Builds the CDT of all vertices and segments; maps PSLG vertices to handles.
/// \throws geometry_error on duplicate vertices or intersecting segments.
inline void build_cdt(const pslg& g, loop_triangulation& t) {
  std::vector<std::pair<epick::Point_2, index_t>> pts;
  pts.reserve(g.vertices.size());
  for (std::size_t i = 0; i < g.vertices.size(); ++i)
    pts.emplace_back(to_cgal(g.vertices[i]), static_cast<index_t>(i));
  t.cdt.insert(pts.begin(), pts.end());
  t.vertex.assign(g.vertices.size(), pslg_cdt::Vertex_handle());
  for (auto v = t.cdt.finite_vertices_begin(); v != t.cdt.finite_vertices_end(); ++v)
    t.vertex[v->info()] = v;
  for (std::size_t i = 0; i < g.vertices.size(); ++i)
    if (t.vertex[i] == pslg_cdt::Vertex_handle() || t.vertex[i]->info() != i) {
      const index_t j = t.cdt.insert(pts[i].first)->info();
      throw geometry_error("duplicate vertices " + std::to_string(std::min<std::size_t>(i, j)) +
                               " and " + std::to_string(std::max<std::size_t>(i, j)) +
                               " have the same coordinates",
                           {std::min<std::size_t>(i, j), std::max<std::size_t>(i, j)});
    }
  try {
    for (const segment& s : g.segments)
      t.cdt.insert_constraint(t.vertex[s.a], t.vertex[s.b]);
  } catch (const pslg_cdt::Intersection_of_constraints_exception&) {
    throw geometry_error("segments intersect (cross, overlap or pass through a vertex); "
                         "pdd::validate names them");
  }
  index_t id = 0;
  for (auto f = t.cdt.finite_faces_begin(); f != t.cdt.finite_faces_end(); ++f) {
    f->info().id = id++;
    t.faces.push_back(f);
  }
}

} // namespace detail
} // namespace pdd
