/// \file point_set_cuts.hpp
/// Implementation detail of the strips of a large vertex set (point_set_strips.hpp): the
/// Gabriel graph of the vertices, the cut lines that balance the strips' areas, and the cut
/// ends, where a separator meets the hull (the foot of a perpendicular from a vertex).
#pragma once

#include <pdd/core/kernel.hpp>
#include <pdd/core/point.hpp>
#include <pdd/triangle/detail/mesh_tables.hpp>
#include <pdd/triangle/detail/point_set.hpp>

#include <CGAL/enum.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

namespace pdd::triangle::detail {

/// The Gabriel edges of a vertex set's Delaunay triangulation d as neighbour lists (by input
/// id): the edges whose opposite vertices lie outside or on the disk with the edge as diameter
/// (CGAL's exact side_of_bounded_circle; d being Delaunay, no vertex lies inside it then).
/// Complexity O(n log n).
inline std::vector<std::vector<index_t>> gabriel_neighbours(const std::vector<point>& v,
                                                            const point_set_delaunay& d) {
  const auto at = [&v](index_t i) { return epick::Point_2(v[i].x, v[i].y); };
  std::vector<std::pair<std::uint64_t, bool>> sides; // (edge, an opposite vertex inside)
  sides.reserve(3 * d.triangles.size());
  for (const auto& t : d.triangles)
    for (int i = 0; i < 3; ++i) {
      const index_t a = t[i], b = t[(i + 1) % 3], c = t[(i + 2) % 3];
      sides.emplace_back(edge_key(a, b), CGAL::side_of_bounded_circle(at(a), at(b), at(c)) ==
                                             CGAL::ON_BOUNDED_SIDE);
    }
  std::sort(sides.begin(), sides.end());
  std::vector<std::vector<index_t>> out(v.size());
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i;
    bool inside = false;
    for (; j < sides.size() && sides[j].first == sides[i].first; ++j)
      inside = inside || sides[j].second;
    const auto a = static_cast<index_t>(sides[i].first >> 32);
    const auto b = static_cast<index_t>(sides[i].first & 0xffffffffu);
    if (!inside) {
      out[a].push_back(b);
      out[b].push_back(a);
    }
    i = j;
  }
  return out;
}

/// Coordinate `axis` (0: x, 1: y) of p.
inline double along(point p, int axis) noexcept {
  return axis == 0 ? p.x : p.y;
}

/// The area of the part of the convex polygon `poly` (counter-clockwise) where coordinate
/// `axis` is at most c (the polygon clipped by that half-plane).
inline double area_up_to(const std::vector<point>& poly, int axis, double c) {
  std::vector<point> clipped;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const point a = poly[i], b = poly[(i + 1) % poly.size()];
    const double ua = along(a, axis) - c, ub = along(b, axis) - c;
    if (ua <= 0.0) clipped.push_back(a);
    if ((ua < 0.0 && ub > 0.0) || (ua > 0.0 && ub < 0.0)) {
      const double s = ua / (ua - ub);
      clipped.push_back({a.x + s * (b.x - a.x), a.y + s * (b.y - a.y)});
    }
  }
  double twice = 0.0;
  for (std::size_t i = 0; i < clipped.size(); ++i) {
    const point a = clipped[i], b = clipped[(i + 1) % clipped.size()];
    twice += a.x * b.y - a.y * b.x;
  }
  return 0.5 * twice;
}

/// The n - 1 cut positions along `axis` that split the convex polygon into n parts of equal
/// area (bisection on area_up_to).
inline std::vector<double> balanced_cuts(const std::vector<point>& poly, int axis, std::size_t n) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const point p : poly) {
    lo = std::min(lo, along(p, axis));
    hi = std::max(hi, along(p, axis));
  }
  const double total = area_up_to(poly, axis, hi);
  std::vector<double> cuts;
  for (std::size_t j = 1; j < n; ++j) {
    double a = lo, b = hi;
    for (int it = 0; it < 60; ++it) {
      const double m = 0.5 * (a + b);
      (area_up_to(poly, axis, m) < total * static_cast<double>(j) / static_cast<double>(n) ? a
                                                                                           : b) = m;
    }
    cuts.push_back(0.5 * (a + b));
  }
  return cuts;
}

/// The angle in degrees at b between the rays b->a and b->c.
inline double angle_deg(point a, point b, point c) noexcept {
  const double ux = a.x - b.x, uy = a.y - b.y, wx = c.x - b.x, wy = c.y - b.y;
  return std::atan2(std::abs(ux * wy - uy * wx), ux * wx + uy * wy) * 180.0 / std::numbers::pi;
}

} // namespace pdd::triangle::detail

namespace pdd::triangle::detail {

/// Where a separator may meet the hull: the foot `at` of the perpendicular from the inner
/// vertex w onto the hull edge a -> b (counter-clockwise; rounded to double, so within
/// rounding of the edge, on either side of it), which it then splits; or, where that foot is
/// a hull vertex (`vertex`, between hull edges a -> vertex -> b: points on a grid), that vertex.
struct cut_end {
  point at;
  index_t w = no_index, a = no_index, b = no_index;
  index_t vertex = no_index;
};

/// The vertices of `sorted` (ids sorted by coordinate `axis`) within `band` of the line
/// {coordinate `axis` = c}: a range of it.
inline std::pair<std::size_t, std::size_t> band_range(const std::vector<point>& v,
                                                      const std::vector<index_t>& sorted, int axis,
                                                      double c, double band) {
  const auto key = [&](index_t i) { return along(v[i], axis); };
  const auto lo = std::lower_bound(sorted.begin(), sorted.end(), c - band,
                                   [&](index_t i, double x) { return key(i) < x; });
  const auto hi = std::upper_bound(sorted.begin(), sorted.end(), c + band,
                                   [&](double x, index_t i) { return x < key(i); });
  return {static_cast<std::size_t>(lo - sorted.begin()),
          static_cast<std::size_t>(hi - sorted.begin())};
}

/// Whether the disk with diameter p-q holds none of the vertices `sorted[range]` (exact).
inline bool disk_empty(const std::vector<point>& v, const std::vector<index_t>& sorted,
                       std::pair<std::size_t, std::size_t> range, point p, point q) {
  const epick::Point_2 cp(p.x, p.y), cq(q.x, q.y);
  for (std::size_t k = range.first; k < range.second; ++k) {
    const point x = v[sorted[k]];
    if (x != p &&
        CGAL::side_of_bounded_circle(cp, cq, epick::Point_2(x.x, x.y)) == CGAL::ON_BOUNDED_SIDE)
      return false;
  }
  return true;
}

/// What the cut ends are chosen from: the vertices off the hull and all distinct vertices,
/// sorted along the axis, each vertex's distance to its nearest neighbour, and the shortest
/// edge a separator may have.
struct cut_candidates {
  std::vector<index_t> inner, all;
  std::vector<double> nearest;
  int axis = 0;
  double min_length = 0.0;
};

/// The feet of the perpendiculars from the inner vertices within `band` of the line
/// {coordinate axis = c} onto the hull edge a -> b, with their distances: those strictly
/// inside the edge and within the band, at least min_length from the edge's ends and from their
/// vertex and at most a path edge's longest length (half a strip's width, 0.5 / 0.35 band),
/// whose vertex's nearest neighbour is at least min_length away; and a foot on hull vertex a
/// itself (after hull vertex `before`) where the perpendicular meets both hull edges there at
/// >= 61 deg.
inline std::vector<std::pair<double, cut_end>> feet_on(const std::vector<point>& v,
                                                       const cut_candidates& cc, index_t before,
                                                       index_t a, index_t b, double c,
                                                       double band) {
  const point pa = v[a], pb = v[b];
  const double dx = pb.x - pa.x, dy = pb.y - pa.y, len = std::hypot(dx, dy);
  std::vector<std::pair<double, cut_end>> feet;
  const auto [first, last] = band_range(v, cc.inner, cc.axis, c, band);
  const double max_dist = band / 0.35 * 0.5; // a path edge's longest (strip_separators)
  for (std::size_t k = first; k < last; ++k) {
    const index_t w = cc.inner[k];
    const double t = ((v[w].x - pa.x) * dx + (v[w].y - pa.y) * dy) / (len * len);
    const point foot{pa.x + t * dx, pa.y + t * dy};
    const double dist = std::hypot(v[w].x - foot.x, v[w].y - foot.y);
    if (foot == pa && dist >= cc.min_length && dist <= max_dist && cc.nearest[w] >= cc.min_length &&
        angle_deg(v[before], pa, v[w]) >= 61.0 && angle_deg(pb, pa, v[w]) >= 61.0) {
      feet.push_back({dist, cut_end{foot, w, before, b, a}});
      continue;
    }
    if (t * len < cc.min_length || (1.0 - t) * len < cc.min_length || dist < cc.min_length ||
        dist > max_dist || cc.nearest[w] < cc.min_length || foot == pa || foot == pb ||
        std::abs(along(foot, cc.axis) - c) > band)
      continue;
    feet.push_back({dist, cut_end{foot, w, a, b}});
  }
  return feet;
}

/// The cut ends on hull edge a -> b near the line {coordinate axis = c} (feet_on), nearest to
/// the edge first, whose disk on the vertex and its foot holds no vertex (exact; a vertex in
/// that disk is nearer the edge than the disk's vertex, so the nearest ones are tried): at
/// most 8 (of the 64 nearest), tried in that order by the path search.
inline std::vector<cut_end> cut_ends_on(const std::vector<point>& v, const cut_candidates& cc,
                                        index_t before, index_t a, index_t b, double c,
                                        double band) {
  std::vector<std::pair<double, cut_end>> feet = feet_on(v, cc, before, a, b, c, band);
  std::sort(feet.begin(), feet.end(), [](const auto& x, const auto& y) {
    return x.first < y.first || (x.first == y.first && x.second.w < y.second.w);
  });
  const auto near = band_range(v, cc.all, cc.axis, c, 2.0 * band);
  std::vector<cut_end> out;
  for (std::size_t i = 0; i < feet.size() && out.size() < 8 && i < 64; ++i)
    if (disk_empty(v, cc.all, near, v[feet[i].second.w], feet[i].second.at))
      out.push_back(feet[i].second);
  return out;
}

/// The cut ends of the line {coordinate axis = c} on the convex hull (`hull` counter-clockwise):
/// [0] on the hull edge the line crosses where the coordinate grows along the hull, [1] where
/// it falls (cut_ends_on). False when the line passes through a hull vertex or a side has no
/// cut end.
inline bool find_cut_ends(const std::vector<point>& v, const std::vector<index_t>& hull,
                          const cut_candidates& cc, double c, double band,
                          std::array<std::vector<cut_end>, 2>& ends) {
  int found = 0;
  for (std::size_t k = 0; k < hull.size(); ++k) {
    const index_t a = hull[k], b = hull[(k + 1) % hull.size()];
    const double ua = along(v[a], cc.axis) - c, ub = along(v[b], cc.axis) - c;
    if (ua == 0.0) return false;
    if ((ua < 0.0) == (ub < 0.0) || ub == 0.0) continue;
    std::vector<cut_end>& side = ends[ua < 0.0 ? 0 : 1];
    side = cut_ends_on(v, cc, hull[(k + hull.size() - 1) % hull.size()], a, b, c, band);
    if (side.empty()) return false;
    ++found;
  }
  return found == 2;
}

} // namespace pdd::triangle::detail
