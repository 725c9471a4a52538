// Hand-made and random domains for the kernel and mesh tests. Every input angle measured on the
// meshed side is >= 60 degrees, so Delaunay refinement with the default 20.7-degree bound must
// terminate with every triangle meeting the bounds.
#pragma once

#include <pdd/core/pslg.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

namespace pdd::test {

inline pslg unit_square(int marker = 1) {
  pslg d;
  d.add_loop(std::vector<point>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, marker);
  return d;
}

/// The unit square with a notch 1e-4 wide and deep in its bottom side (a feature far smaller
/// than the mesh: the geometric path's test domain; angles 90 and 270 deg: no shields).
inline pslg notched_square() {
  pslg g;
  g.add_loop(
      std::vector<point>{
          {0, 0}, {0.5, 0}, {0.5, 1e-4}, {0.5001, 1e-4}, {0.5001, 0}, {1, 0}, {1, 1}, {0, 1}},
      0);
  return g;
}

/// [0,3]^2 with the hole [1,2]^2 (clockwise, marker 2) and its hole point.
inline pslg square_with_hole() {
  pslg d;
  d.add_loop(std::vector<point>{{0, 0}, {3, 0}, {3, 3}, {0, 3}}, 1);
  d.add_loop(std::vector<point>{{1, 1}, {1, 2}, {2, 2}, {2, 1}}, 2);
  d.holes.push_back({1.5, 1.5});
  return d;
}

/// An L of three unit squares (reflex corner at (1, 1)), clockwise.
inline pslg l_shape() {
  pslg d;
  d.add_loop(std::vector<point>{{0, 0}, {0, 2}, {1, 2}, {1, 1}, {2, 1}, {2, 0}}, 1);
  return d;
}

/// A 4 x 2 rectangle with a square hole and a hexagonal hole.
inline pslg two_holes() {
  pslg d;
  d.add_loop(std::vector<point>{{0, 0}, {4, 0}, {4, 2}, {0, 2}}, 1);
  d.add_loop(std::vector<point>{{0.5, 0.5}, {1.5, 0.5}, {1.5, 1.5}, {0.5, 1.5}}, 2);
  std::vector<point> hex;
  for (int i = 0; i < 6; ++i) {
    const double t = std::numbers::pi / 3 * i;
    hex.push_back({3 + 0.5 * std::cos(t), 1 + 0.5 * std::sin(t)});
  }
  d.add_loop(hex, 3);
  d.holes.push_back({1, 1});
  d.holes.push_back({3, 1});
  return d;
}

/// A heptagon-like polygon whose vertices and segments all carry different markers.
inline pslg marker_polygon() {
  pslg d;
  const std::vector<point> pts{{0, 0},     {2, -0.3},  {3.1, 0.8}, {2.9, 2.2},
                               {1.7, 3.0}, {0.2, 2.6}, {-0.6, 1.2}};
  for (std::size_t i = 0; i < pts.size(); ++i)
    d.add_vertex(pts[i], 10 + static_cast<int>(i));
  for (index_t i = 0; i < pts.size(); ++i)
    d.add_segment(i, (i + 1) % static_cast<index_t>(pts.size()), 20 + static_cast<int>(i));
  return d;
}

inline double uniform01(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

/// Angle at b from ray b->c counter-clockwise to ray b->a, in degrees [0, 360): the interior
/// angle at b of a counter-clockwise polygon ... a, b, c ...
inline double ccw_angle_deg(point a, point b, point c) {
  const double t1 = std::atan2(c.y - b.y, c.x - b.x);
  const double t2 = std::atan2(a.y - b.y, a.x - b.x);
  double d = (t2 - t1) * 180.0 / std::numbers::pi;
  while (d < 0)
    d += 360.0;
  while (d >= 360.0)
    d -= 360.0;
  return d;
}

/// Smallest interior angle of a counter-clockwise polygon.
inline double min_interior_angle(const std::vector<point>& p) {
  double m = 360;
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i)
    m = std::min(m, ccw_angle_deg(p[(i + n - 1) % n], p[i], p[(i + 1) % n]));
  return m;
}

inline double dist_point_segment(point p, point a, point b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  double t = ((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy);
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

/// Crossing-number point-in-polygon test.
inline bool inside_polygon(point p, const std::vector<point>& poly) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const point a = poly[i], b = poly[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
  }
  return in;
}

/// A random star-shaped outer polygon (8..15 vertices, radius 0.6..1 around the origin, every
/// interior angle >= 62 degrees, possibly reflex) with 0..3 holes that are convex polygons
/// (6..9 vertices, clockwise or not at random), well inside and apart. All angles on the
/// meshed side are >= 60 degrees. Deterministic in the seed.
inline pslg random_domain_60(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<point> outer;
  for (;;) {
    const int n = 8 + static_cast<int>(rng() % 8);
    outer.clear();
    for (int i = 0; i < n; ++i) {
      const double t = (i + 0.8 * uniform01(rng) - 0.4) * 2 * std::numbers::pi / n;
      const double r = 0.6 + 0.4 * uniform01(rng);
      outer.push_back({r * std::cos(t), r * std::sin(t)});
    }
    if (min_interior_angle(outer) >= 62.0) break;
  }
  pslg d;
  d.add_loop(outer, 1);
  const int holes = static_cast<int>(rng() % 4);
  std::vector<std::pair<point, double>> placed;
  for (int h = 0, tries = 0; h < holes && tries < 200; ++tries) {
    const double r = 0.06 + 0.08 * uniform01(rng);
    const point c{(2 * uniform01(rng) - 1) * 0.5, (2 * uniform01(rng) - 1) * 0.5};
    bool ok = inside_polygon(c, outer);
    for (std::size_t i = 0; i < outer.size() && ok; ++i)
      ok = dist_point_segment(c, outer[i], outer[(i + 1) % outer.size()]) > 2.5 * r;
    for (const auto& [pc, pr] : placed)
      ok = ok && std::hypot(c.x - pc.x, c.y - pc.y) > 2.0 * (r + pr);
    if (!ok) continue;
    const int n = 6 + static_cast<int>(rng() % 4);
    std::vector<point> hole;
    const double phase = uniform01(rng);
    for (int i = 0; i < n; ++i) {
      const double t = (i + phase) * 2 * std::numbers::pi / n;
      hole.push_back({c.x + r * std::cos(t), c.y + r * std::sin(t)});
    }
    if (rng() % 2) std::reverse(hole.begin(), hole.end());
    d.add_loop(hole, 2 + h);
    d.holes.push_back(c);
    placed.push_back({c, r});
    ++h;
  }
  return d;
}

} // namespace pdd::test
