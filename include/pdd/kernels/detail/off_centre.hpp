/// \file off_centre.hpp
/// The refinement point of both kernels for a bad triangle: Üngör's off-centre where it is
/// nearer than the circumcentre (A. Üngör, Off-centers: a new type of Steiner points for
/// computing size-optimal quality-guaranteed Delaunay triangulations, LATIN 2004).
///
/// For a triangle with shortest edge pq (midpoint m) and circumcentre c, the off-centre is the
/// point o of the segment mc at distance h = 0.95 (|pq| / 2) cot(theta / 2) from m, where theta
/// is the angle bound: the isosceles triangle p q o has the apex angle 2 atan(tan(theta / 2) /
/// 0.95) > theta, so it meets the bound with 5 % to spare for rounding. Since
/// |mc| = (|pq| / 2) cot(phi) for the triangle's smallest angle phi, o is taken only when phi is
/// below about theta / 2; any other triangle (among them every triangle bad by its area alone,
/// whose smallest angle is at least theta) keeps its circumcentre.
///
/// Why the guarantees stand (dissertation Theorem 1, Proposition 12, Theorem 15): the
/// triangle's circumdisk is empty and holds o (it holds m and c, and o lies between them), so
/// o's nearest vertex is at least R - |co| = R - |mc| + h > h away (R the circumradius); with
/// theta = 20.7 deg, h = 2.6 |pq|, more than the sqrt(2) |pq| that Ruppert's analysis gives
/// the circumcentre of a bad triangle. Every bound on edge lengths that the analysis derives
/// from insertion radii, and so the decoupling path's (no separator piece is ever split), holds
/// for o as for c. An o beyond a segment lies in the circumdisk's part beyond it, which the
/// segment's diametral disk contains: o encroaches it, and the segment is split instead, as
/// for a circumcentre. Triangle 1.6 inserts off-centres too (with the same 0.95 margin), which
/// is why its meshes have fewer triangles than circumcentre refinement gives.
#pragma once

#include <pdd/core/point.hpp>

#include <cmath>
#include <limits>

namespace pdd::detail {

/// The refinement point of triangle (v0, v1, v2) with circumcentre `circumcentre` under the
/// shape bound B = sin^2(theta) (0: no angle bound, the circumcentre): its off-centre where
/// that is nearer to its shortest edge (file comment), else the circumcentre.
inline point off_centre(const point& v0, const point& v1, const point& v2,
                        const point& circumcentre, double shape_bound) {
  if (!(shape_bound > 0.0 && shape_bound < 1.0)) return circumcentre;
  const point* corner[3] = {&v0, &v1, &v2};
  int opposite = 0; // the shortest edge is the one opposite corner[opposite]
  double shortest2 = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    const point &a = *corner[(i + 1) % 3], &b = *corner[(i + 2) % 3];
    const double len2 = (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y);
    if (len2 < shortest2) opposite = i, shortest2 = len2;
  }
  const point &a = *corner[(opposite + 1) % 3], &b = *corner[(opposite + 2) % 3];
  const double mx = 0.5 * (a.x + b.x), my = 0.5 * (a.y + b.y);
  const double cos_theta = std::sqrt(1.0 - shape_bound);
  const double cot_half_theta = std::sqrt((1.0 + cos_theta) / (1.0 - cos_theta));
  const double h = 0.95 * 0.5 * std::sqrt(shortest2) * cot_half_theta;
  const double dx = circumcentre.x - mx, dy = circumcentre.y - my;
  const double d = std::sqrt(dx * dx + dy * dy);
  if (!(d > h)) return circumcentre;
  return point{mx + dx * (h / d), my + dy * (h / d)};
}

} // namespace pdd::detail
