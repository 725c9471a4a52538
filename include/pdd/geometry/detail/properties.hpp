/// \file properties.hpp
/// Implementation of pdd's domain properties: the counter-clockwise angle at a vertex and the
/// smallest angle on the domain side of the loops.
#pragma once

#include <pdd/core/index.hpp>
#include <pdd/core/point.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/geometry/loop_structure.hpp>

#include <cmath>
#include <cstddef>
#include <numbers>

namespace pdd::detail {

/// Angle in degrees at v, turning counter-clockwise from direction v->to_ccw_from to
/// direction v->to; in (0, 360).
inline double ccw_angle_deg(const point& v, const point& from, const point& to) {
  const double ax = from.x - v.x, ay = from.y - v.y, bx = to.x - v.x, by = to.y - v.y;
  double a = std::atan2(ax * by - ay * bx, ax * bx + ay * by);
  if (a < 0) a += 2 * std::numbers::pi;
  return a * 180.0 / std::numbers::pi;
}

/// Smallest domain-side angle over all loop vertices; the vertex in *vertex.
inline double min_domain_angle_deg(const pslg& g, const loop_structure& ls, index_t* vertex) {
  double best = 360.0;
  index_t where = no_index;
  for (const polygon_loop& l : ls.loops) {
    const std::size_t n = l.vertices.size();
    for (std::size_t i = 0; i < n; ++i) {
      const point& prev = g.vertices[l.vertices[(i + n - 1) % n]];
      const point& v = g.vertices[l.vertices[i]];
      const point& next = g.vertices[l.vertices[(i + 1) % n]];
      // domain on the left of prev -> v -> next: the angle from v->next round to v->prev
      const double a =
          l.domain_on_left() ? ccw_angle_deg(v, next, prev) : ccw_angle_deg(v, prev, next);
      if (a < best || (a == best && l.vertices[i] < where)) {
        best = a;
        where = l.vertices[i];
      }
    }
  }
  if (vertex) *vertex = where;
  return best;
}

} // namespace pdd::detail
