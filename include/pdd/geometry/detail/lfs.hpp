/// \file detail/lfs.hpp
/// Implementation of pdd/geometry/lfs.hpp: the minimum local feature size (Definition 7)
/// from the labelled constrained Delaunay triangulation of the PSLG.
#pragma once

#include <pdd/geometry/loops.hpp>

#include <CGAL/Kernel/global_functions.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace pdd::detail {

/// Euclidean distance of two points.
inline double point_distance(const epick::Point_2& p, const epick::Point_2& q) {
  const double dx = p.x() - q.x(), dy = p.y() - q.y();
  return std::sqrt(dx * dx + dy * dy);
}

/// True if the closest point of segment ab to p lies in the open segment (both angles at a
/// and b of triangle p, a, b acute; exact predicate).
inline bool foot_in_interior(const epick::Point_2& p, const epick::Point_2& a,
                             const epick::Point_2& b) {
  return CGAL::angle(p, a, b) == CGAL::ACUTE && CGAL::angle(p, b, a) == CGAL::ACUTE;
}

/// Distance of p from the line through a and b (|cross| / |ab|).
inline double line_distance(const epick::Point_2& p, const epick::Point_2& a,
                            const epick::Point_2& b) {
  const double ux = b.x() - a.x(), uy = b.y() - a.y();
  return std::abs(ux * (p.y() - a.y()) - uy * (p.x() - a.x())) / std::sqrt(ux * ux + uy * uy);
}

/// Distance of p from the closed segment ab.
inline double segment_distance(const epick::Point_2& p, const epick::Point_2& a,
                               const epick::Point_2& b) {
  if (foot_in_interior(p, a, b)) return line_distance(p, a, b);
  return std::min(point_distance(p, a), point_distance(p, b));
}

/// The closest point of the line through a and b to p (inexact construction).
inline epick::Point_2 foot_point(const epick::Point_2& p, const epick::Point_2& a,
                                 const epick::Point_2& b) {
  const double ux = b.x() - a.x(), uy = b.y() - a.y();
  const double t = ((p.x() - a.x()) * ux + (p.y() - a.y()) * uy) / (ux * ux + uy * uy);
  return {a.x() + t * ux, a.y() + t * uy};
}

/// True if the straight segment from vertex v to x (a point on a constrained edge of face
/// `target`, seen from inside target) crosses no constrained edge and passes through no
/// vertex before it enters `target`: then it lies in the closure of the domain. Walks the
/// faces the segment crosses (exact orientation predicates on v, x and face vertices).
/// A walk through a vertex w answers false; that is safe for lfs_min because |vw| < |vx|
/// and vw is then a shorter admissible vertex-vertex distance.
/// The face around vertex v that the segment from v to x enters, with its vertices right and
/// left of the segment; false if the segment runs along an edge through a vertex or enters
/// no finite face (then it is not visible in the sense of visible_in_domain).
inline bool first_face_towards(const loop_triangulation& t, pslg_cdt::Vertex_handle v,
                               const epick::Point_2& x, pslg_cdt::Face_handle& f,
                               pslg_cdt::Vertex_handle& left, pslg_cdt::Vertex_handle& right) {
  const auto& vp = v->point();
  auto fc = t.cdt.incident_faces(v);
  const auto done = fc;
  do {
    if (t.cdt.is_infinite(fc)) continue;
    const int i = fc->index(v);
    const auto p = fc->vertex(pslg_cdt::ccw(i)), q = fc->vertex(pslg_cdt::cw(i));
    const auto o1 = CGAL::orientation(vp, p->point(), x);
    const auto o2 = CGAL::orientation(vp, q->point(), x);
    if (o1 == CGAL::LEFT_TURN && o2 == CGAL::RIGHT_TURN) {
      f = fc;
      right = p;
      left = q;
      return true;
    }
    if ((o1 == CGAL::COLLINEAR && CGAL::angle(p->point(), vp, x) == CGAL::ACUTE) ||
        (o2 == CGAL::COLLINEAR && CGAL::angle(q->point(), vp, x) == CGAL::ACUTE))
      return false; // along an edge, through a vertex
  } while (++fc != done);
  return false;
}

/// True if the straight segment from vertex v to x (a point on a constrained edge of face
/// `target`, seen from inside target) crosses no constrained edge and passes through no
/// vertex before it enters `target`: then it lies in the closure of the domain. Walks the
/// faces the segment crosses (exact orientation predicates on v, x and face vertices).
/// A walk through a vertex w answers false; that is safe for lfs_min because |vw| < |vx|
/// and vw is then a shorter admissible vertex-vertex distance.
inline bool visible_in_domain(const loop_triangulation& t, pslg_cdt::Vertex_handle v,
                              const epick::Point_2& x, pslg_cdt::Face_handle target) {
  const auto& vp = v->point();
  if (vp == x) return true;
  pslg_cdt::Face_handle f;
  pslg_cdt::Vertex_handle left, right;
  if (!first_face_towards(t, v, x, f, left, right)) return false;
  for (std::size_t steps = 0; steps <= t.faces.size(); ++steps) {
    if (f == target) return true;
    const int i = 3 - f->index(left) - f->index(right);
    if (f->is_constrained(i)) return false;
    const auto n = f->neighbor(i);
    if (t.cdt.is_infinite(n)) return false;
    const auto w = n->vertex(n->index(f));
    const auto o = CGAL::orientation(vp, x, w->point());
    if (o == CGAL::LEFT_TURN)
      left = w;
    else if (o == CGAL::RIGHT_TURN)
      right = w;
    else
      return false;
    f = n;
  }
  return false;
}

/// Distance of point p from a finite triangle (p is never strictly inside one of the faces
/// visited: it is a triangulation vertex, so the distance is that to the boundary).
inline double face_distance(const epick::Point_2& p, pslg_cdt::Face_handle f) {
  double d = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i)
    d = std::min(d, segment_distance(p, f->vertex(i)->point(), f->vertex((i + 1) % 3)->point()));
  return d;
}

/// Step 1 of lfs_min: the length of the shortest CDT edge with a domain face on one side.
inline double shortest_domain_edge(const loop_triangulation& t) {
  double best = std::numeric_limits<double>::infinity();
  for (auto e = t.cdt.finite_edges_begin(); e != t.cdt.finite_edges_end(); ++e) {
    const auto f = e->first, n = f->neighbor(e->second);
    if (!((!t.cdt.is_infinite(f) && in_domain(f)) || (!t.cdt.is_infinite(n) && in_domain(n))))
      continue;
    best = std::min(best, point_distance(f->vertex(pslg_cdt::cw(e->second))->point(),
                                         f->vertex(pslg_cdt::ccw(e->second))->point()));
  }
  return best;
}

/// Step 2 of lfs_min for vertex vi: min(best, the distance to every constrained edge whose
/// foot from vi lies in its interior and is visible in the domain), by a breadth-first
/// search over domain faces pruned at best. stamp (per face, the last vertex that queued
/// it) and queue are scratch space reused across vertices.
inline double nearest_visible_segment(const loop_triangulation& t, index_t vi, double best,
                                      std::vector<index_t>& stamp,
                                      std::vector<pslg_cdt::Face_handle>& queue) {
  const auto v = t.vertex[vi];
  const auto& p = v->point();
  queue.clear();
  auto fc = t.cdt.incident_faces(v);
  const auto done = fc;
  do {
    if (t.cdt.is_infinite(fc) || !in_domain(fc)) continue;
    stamp[fc->info().id] = vi;
    queue.push_back(fc);
  } while (++fc != done);
  for (std::size_t qi = 0; qi < queue.size(); ++qi) {
    const auto f = queue[qi];
    for (int i = 0; i < 3; ++i) {
      if (f->is_constrained(i)) {
        const auto a = f->vertex(pslg_cdt::cw(i)), b = f->vertex(pslg_cdt::ccw(i));
        if (a == v || b == v || !foot_in_interior(p, a->point(), b->point())) continue;
        const double d = line_distance(p, a->point(), b->point());
        if (d < best && visible_in_domain(t, v, foot_point(p, a->point(), b->point()), f)) best = d;
        continue;
      }
      const auto n = f->neighbor(i);
      if (t.cdt.is_infinite(n) || stamp[n->info().id] == vi) continue;
      stamp[n->info().id] = vi;
      // the slack keeps faces whose rounded distance ties the minimum
      if (face_distance(p, n) <= best * (1.0 + 1e-12)) queue.push_back(n);
    }
  }
  return best;
}

/// Minimum local feature size (Definition 7) of a PSLG from its labelled triangulation.
///
/// 1. Vertex-vertex: the minimising pair is an edge of the CDT (a shorter visible vertex
///    would otherwise lie in the pair's diametral disk), so the shortest CDT edge with a
///    domain face on one side gives the best vertex-vertex distance.
/// 2. Vertex-segment with the foot inside the segment: from every vertex v a breadth-first
///    search over domain faces across unconstrained edges, pruned at the current minimum,
///    reaches every constrained edge whose perpendicular from v lies in the domain; a
///    candidate counts only if the walk from v to its foot stays in the domain.
/// Segment-segment distances of non-incident segments are vertex-segment distances.
/// Complexity O(n log n) for the CDT plus O(n) expected for the searches (each explores
/// the faces within the current minimum of a vertex).
inline double lfs_min(const pslg& g, const loop_triangulation& t) {
  double best = shortest_domain_edge(t);
  std::vector<index_t> stamp(t.faces.size(), no_index);
  std::vector<pslg_cdt::Face_handle> queue;
  for (index_t vi = 0; vi < g.vertices.size(); ++vi)
    best = nearest_visible_segment(t, vi, best, stamp, queue);
  return best;
}

} // namespace pdd::detail
