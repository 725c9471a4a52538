/// \file ray_order.hpp
/// The counter-clockwise order of rays from one point, decided with CGAL's exact orientation
/// predicate: which segment comes next around a vertex (the face walk of a general PSLG), and
/// which sector of the domain at a vertex holds a triangle (shield statistics at pinch
/// vertices).
#pragma once

#include <pdd/core/kernel.hpp>
#include <pdd/core/point.hpp>

namespace pdd {

/// Where ray v -> p lies turning counter-clockwise from ray v -> ref: 0 on ray v -> ref, 1 in
/// (0, 180) deg, 2 at 180 deg, 3 in (180, 360) deg (exact). \pre p != v, ref != v.
inline int ray_turn_class(point v, point ref, point p) {
  const epick::Point_2 pv(v.x, v.y), pr(ref.x, ref.y), pp(p.x, p.y);
  const auto o = CGAL::orientation(pv, pr, pp);
  if (o == CGAL::LEFT_TURN) return 1;
  if (o == CGAL::RIGHT_TURN) return 3;
  // collinear: the same direction when p lies on the side of v that ref does (the signs of
  // differences of doubles are exact)
  const auto sign = [](double d) { return (d > 0.0) - (d < 0.0); };
  const int sx = sign(p.x - v.x), sy = sign(p.y - v.y);
  const bool same = (sx != 0 && sx == sign(ref.x - v.x)) || (sy != 0 && sy == sign(ref.y - v.y));
  return same ? 0 : 2;
}

/// True when ray v -> p comes strictly before ray v -> q turning counter-clockwise from ray
/// v -> ref (exact). \pre p, q, ref != v.
inline bool ray_turns_before(point v, point ref, point p, point q) {
  const int cp = ray_turn_class(v, ref, p), cq = ray_turn_class(v, ref, q);
  if (cp != cq) return cp < cq;
  if (cp == 0 || cp == 2) return false; // the same ray
  return CGAL::orientation(epick::Point_2(v.x, v.y), epick::Point_2(p.x, p.y),
                           epick::Point_2(q.x, q.y)) == CGAL::LEFT_TURN;
}

} // namespace pdd
