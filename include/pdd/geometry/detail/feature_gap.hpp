/// \file detail/feature_gap.hpp
/// Implementation of pdd/geometry/feature_gap.hpp: the features near every triangle of the
/// domain's constrained Delaunay triangulation, the domain-side angle at every vertex and the
/// distance of a point from a feature.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/geometry/detail/lfs.hpp>
#include <pdd/geometry/loops.hpp>
#include <pdd/geometry/properties.hpp>

#include <CGAL/Kernel/global_functions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace pdd {

/// A vertex or a segment of a PSLG, by its index.
struct pslg_feature {
  enum class kind : unsigned char { vertex, segment };
  kind type = kind::vertex;
  index_t id = no_index;
  friend bool operator==(const pslg_feature&, const pslg_feature&) = default;
};

namespace detail {

/// Per loop vertex: the domain-side angle (degrees) and, per segment, its ends ordered so that
/// the domain lies on the left of a -> b.
struct loop_sides {
  std::vector<double> angle_deg;                   ///< by vertex (360 off the loops)
  std::vector<std::array<index_t, 2>> oriented;    ///< by segment: domain on the left
  std::vector<std::array<index_t, 2>> segments_at; ///< by vertex: its two segments
};

/// The domain-side angle at every loop vertex and every segment oriented with the domain on
/// its left (the loops of pdd::find_loops). Complexity O(n).
inline loop_sides orient_loops(const pslg& g, const loop_structure& ls) {
  loop_sides out;
  out.angle_deg.assign(g.vertices.size(), 360.0);
  out.oriented.assign(g.segments.size(), {no_index, no_index});
  out.segments_at.assign(g.vertices.size(), {no_index, no_index});
  for (const polygon_loop& l : ls.loops) {
    const std::size_t n = l.vertices.size();
    const bool left = l.domain_on_left();
    for (std::size_t i = 0; i < n; ++i) {
      const index_t u = l.vertices[(i + n - 1) % n], v = l.vertices[i], w = l.vertices[(i + 1) % n];
      const point &prev = g.vertices[u], &p = g.vertices[v], &next = g.vertices[w];
      out.angle_deg[v] = left ? ccw_angle_deg(p, next, prev) : ccw_angle_deg(p, prev, next);
      out.oriented[l.segments[i]] = left ? std::array{v, w} : std::array{w, v};
      out.segments_at[v] = {l.segments[(i + n - 1) % n], l.segments[i]};
    }
  }
  return out;
}

/// Appends f to list unless it is there already.
inline void add_feature(std::vector<pslg_feature>& list, pslg_feature f) {
  if (std::find(list.begin(), list.end(), f) == list.end()) list.push_back(f);
}

/// The features of a domain face of the PSLG's triangulation and of its neighbours across
/// unconstrained edges: their vertices and their constrained edges (as PSLG segments); the
/// face's own come first, `own` of them.
inline std::vector<pslg_feature> face_features(const pslg& g, const segment_incidence& inc,
                                               const loop_triangulation& t, pslg_cdt::Face_handle f,
                                               std::size_t& own) {
  std::vector<pslg_feature> out;
  const auto add_face = [&](pslg_cdt::Face_handle h) {
    for (int i = 0; i < 3; ++i) {
      add_feature(out, {pslg_feature::kind::vertex, h->vertex(i)->info()});
      if (!h->is_constrained(i)) continue;
      const index_t s = segment_between(g, inc, h->vertex(pslg_cdt::cw(i))->info(),
                                        h->vertex(pslg_cdt::ccw(i))->info());
      if (s != no_index) add_feature(out, {pslg_feature::kind::segment, s});
    }
  };
  add_face(f);
  own = out.size();
  for (int i = 0; i < 3; ++i) {
    const auto n = f->neighbor(i);
    if (!f->is_constrained(i) && !t.cdt.is_infinite(n) && in_domain(n)) add_face(n);
  }
  return out;
}

/// Distance of x from a feature; a segment of a neighbouring face (`own` false) counts only
/// from its domain side (the left of its oriented ends; exact orientation predicate), else
/// +infinity. (x lies in the closure of the face: a segment of the face itself is always seen
/// from its domain side, even where the rounded x lies a hair behind it.)
inline double feature_distance(const pslg& g, const loop_sides& sides, const point& x,
                               pslg_feature f, bool own) {
  const epick::Point_2 p = to_cgal(x);
  if (f.type == pslg_feature::kind::vertex) return point_distance(p, to_cgal(g.vertices[f.id]));
  const auto& ends = sides.oriented[f.id];
  const epick::Point_2 a = to_cgal(g.vertices[ends[0]]), b = to_cgal(g.vertices[ends[1]]);
  if (!own && CGAL::orientation(a, b, p) == CGAL::RIGHT_TURN)
    return std::numeric_limits<double>::infinity();
  return segment_distance(p, a, b);
}

/// True if vertex v is an end of segment s.
inline bool is_end(const pslg& g, index_t s, index_t v) {
  return g.segments[s].a == v || g.segments[s].b == v;
}

/// The vertex two segments share, or no_index.
inline index_t shared_end(const pslg& g, index_t s, index_t t) {
  const segment &p = g.segments[s], &q = g.segments[t];
  if (p.a == q.a || p.a == q.b) return p.a;
  if (p.b == q.a || p.b == q.b) return p.b;
  return no_index;
}

} // namespace detail
} // namespace pdd
