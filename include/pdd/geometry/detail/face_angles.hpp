/// \file face_angles.hpp
/// The angles of a general PSLG's domain between consecutive segments at a vertex (the sectors
/// whose triangles lie in the domain), on the labelled triangulation of pslg_faces.
#pragma once

#include <pdd/core/index.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/geometry/detail/properties.hpp>
#include <pdd/geometry/detail/pslg_faces.hpp>

namespace pdd::detail {

/// Calls f(vertex, angle_deg, from, to) for every sector of the domain at a PSLG vertex: the sector
/// turning counter-clockwise from one segment of the vertex to the next, when its triangles lie
/// in the domain, turning from the segment to vertex `from` to the segment to vertex `to` (a
/// vertex on one segment has one sector of 360 deg; isolated vertices have none). On closed loops
/// these are the domain-side angles of min_domain_angle_deg. Complexity O(n) after the
/// triangulation.
template <class F>
void for_each_domain_angle(const pslg& g, const pslg_faces& pf, F&& f) {
  const pslg_cdt& cdt = pf.lt.triangulation.cdt;
  for (index_t v = 0; v < g.vertices.size(); ++v) {
    const pslg_cdt::Vertex_handle vh = pf.lt.triangulation.vertex[v];
    // A face (v, a, b), counter-clockwise, follows the edge (v, a) and precedes (v, b).
    auto fc = cdt.incident_faces(vh);
    const auto first = fc;
    bool constrained = true;
    while (!fc->is_constrained(pslg_cdt::cw(fc->index(vh))))
      if (++fc == first) {
        constrained = false; // an isolated vertex
        break;
      }
    if (!constrained) continue;
    const auto start = fc;
    do {
      const index_t from = fc->vertex(pslg_cdt::ccw(fc->index(vh)))->info();
      const point a = g.vertices[from];
      bool in_domain = false, closed = false;
      pslg_cdt::Vertex_handle b;
      do {
        const int i = fc->index(vh);
        in_domain = in_domain || (!cdt.is_infinite(fc) && pf.in_domain(fc));
        b = fc->vertex(pslg_cdt::cw(i));
        closed = fc->is_constrained(pslg_cdt::ccw(i));
        ++fc;
      } while (!closed);
      if (in_domain) {
        const point& bp = g.vertices[b->info()];
        f(v, bp == a ? 360.0 : ccw_angle_deg(g.vertices[v], a, bp), from, b->info());
      }
    } while (fc != start);
  }
}

/// The smallest angle of the domain (for_each_domain_angle); its vertex in *vertex (smallest id
/// on ties). 360 when there is none.
inline double min_face_angle_deg(const pslg& g, const pslg_faces& pf, index_t* vertex) {
  double best = 360.0;
  index_t where = no_index;
  for_each_domain_angle(g, pf, [&](index_t v, double a, index_t, index_t) {
    if (a < best || (a == best && v < where)) {
      best = a;
      where = v;
    }
  });
  if (vertex) *vertex = where;
  return best;
}

} // namespace pdd::detail
