/// \file model_domains.hpp
/// The dissertation's two model domains, generated in code: a key-like domain (about 50
/// segments, one hole) and a pipe-like cross-section (a circle of 576 segments with 9 circular
/// holes). Every input angle, measured inside the domain, is >= 60 degrees, so both mesh with
/// the uniform decoupling method as they are.
#pragma once

#include <pdd/core/pslg.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

namespace pdd {

namespace detail {
/// Points of a regular polygon inscribed in a circle, counter-clockwise from angle phase.
inline std::vector<point> circle_points(point c, double r, std::size_t n, double phase = 0.0) {
  std::vector<point> pts;
  pts.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = phase + 2.0 * std::numbers::pi * static_cast<double>(i) /
                                 static_cast<double>(n);
    pts.push_back({c.x + r * std::cos(t), c.y + r * std::sin(t)});
  }
  return pts;
}
} // namespace detail

/// A key: round bow (24-gon arc, radius 1) with a round hole (12-gon, radius 0.4), a shaft of
/// width 0.5 and length 4 with four rectangular teeth on its lower side. Outer loop marker 1
/// (counter-clockwise), hole marker 2 (clockwise), one hole point. 54 segments; smallest angle
/// in the domain 90 degrees.
inline pslg key_domain() {
  pslg g;
  constexpr double w = 0.25; // half width of the shaft
  const double x0 = std::sqrt(1.0 - w * w);
  const double a0 = std::asin(w); // angle where the shaft leaves the bow
  std::vector<point> outer;
  // Bow: from the upper shaft junction counter-clockwise round to the lower junction.
  constexpr int bow_steps = 22;
  for (int i = 0; i <= bow_steps; ++i) {
    const double t = a0 + (2.0 * std::numbers::pi - 2.0 * a0) * i / bow_steps;
    outer.push_back({std::cos(t), std::sin(t)});
  }
  outer.back() = {x0, -w};
  // Lower side of the shaft with four teeth (each 0.3 deep, 0.35 wide), then the tip.
  double x = x0 + 0.6;
  outer.push_back({x, -w});
  for (int tooth = 0; tooth < 4; ++tooth) {
    outer.push_back({x, -w - 0.3});
    outer.push_back({x + 0.35, -w - 0.3});
    outer.push_back({x + 0.35, -w});
    x += 0.8;
    if (tooth < 3) outer.push_back({x, -w});
  }
  const double tip = x0 + 4.0;
  outer.push_back({tip, -w});
  outer.push_back({tip + 0.25, 0.0});
  outer.push_back({tip, w});
  g.add_loop(outer, 1);
  // The hole, clockwise.
  auto hole = detail::circle_points({-0.2, 0.0}, 0.4, 12);
  std::reverse(hole.begin(), hole.end());
  g.add_loop(hole, 2);
  g.holes.push_back({-0.2, 0.0});
  return g;
}

/// A pipe cross-section: a circle of radius 1 with outer_segments segments (marker 1) and 9
/// circular holes of radius 0.12 with hole_segments segments each (markers 2..10) on a 3x3
/// grid of spacing 0.5. Defaults: 576 + 9 * 64 = 1152 segments.
/// \pre outer_segments >= 6, hole_segments >= 6 (so every angle is >= 120 degrees).
inline pslg pipe_domain(std::size_t outer_segments = 576, std::size_t hole_segments = 64) {
  pslg g;
  g.add_loop(detail::circle_points({0.0, 0.0}, 1.0, outer_segments), 1);
  int marker = 2;
  for (int j = -1; j <= 1; ++j)
    for (int i = -1; i <= 1; ++i) {
      const point c{0.5 * i, 0.5 * j};
      auto hole = detail::circle_points(c, 0.12, hole_segments);
      std::reverse(hole.begin(), hole.end());
      g.add_loop(hole, marker++);
      g.holes.push_back(c);
    }
  return g;
}

} // namespace pdd
