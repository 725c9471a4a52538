/// \file triangle_measures.hpp
/// Triangle measures shared by the meshing criteria, the statistics and the verifier, so that
/// all three compute the same floating-point values from the same coordinates.
#pragma once

#include <pdd/core/point.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <numbers>
#include <vector>

namespace pdd::detail {

/// Twice the signed area of (a, b, c): positive when counter-clockwise (rounded, not exact).
inline double twice_signed_area(const point& a, const point& b, const point& c) noexcept {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

/// Area of the triangle (a, b, c) (absolute value).
inline double triangle_area(const point& a, const point& b, const point& c) noexcept {
  return 0.5 * std::abs(twice_signed_area(a, b, c));
}

/// Signed area of the polygon at(0), ..., at(n - 1) (> 0: counter-clockwise; rounded): the
/// shoelace sum as a fan of twice_signed_area(at(0), at(i), at(i + 1)), i = 1 .. n - 2, in that
/// order. Taking differences to the first vertex loses less to cancellation than the
/// cross-product form sum x_i y_{i+1} - x_{i+1} y_i far from the origin.
template <class PointAt>
double polygon_signed_area(std::size_t n, PointAt&& at) {
  if (n < 3) return 0.0;
  const point o = at(std::size_t{0});
  double twice = 0.0;
  for (std::size_t i = 1; i + 1 < n; ++i)
    twice += twice_signed_area(o, at(i), at(i + 1));
  return 0.5 * twice;
}

/// polygon_signed_area of the closed polygon pts[0], ..., pts[n - 1].
inline double polygon_signed_area(const std::vector<point>& pts) {
  return polygon_signed_area(pts.size(), [&](std::size_t i) { return pts[i]; });
}

/// Centroid of the triangle (a, b, c); the point where sizing fields are sampled.
inline point triangle_centroid(const point& a, const point& b, const point& c) noexcept {
  return {(a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0};
}

inline double squared_distance(const point& a, const point& b) noexcept {
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  return dx * dx + dy * dy;
}

/// sin^2 of the smallest angle of a triangle from twice its signed area and its squared edge
/// lengths, CGAL's shape measure: (2 area)^2 over the product of the two longest squared edge
/// lengths (the smallest angle lies between them).
inline double squared_sine_min_angle(double two_area, double la, double lb, double lc) noexcept {
  const double shortest = std::min({la, lb, lc});
  // la * lb * lc / shortest would round differently; pick the two longest explicitly.
  double p = 0.0;
  if (shortest == la)
    p = lb * lc;
  else if (shortest == lb)
    p = la * lc;
  else
    p = la * lb;
  return two_area * two_area / p;
}

/// sin^2 of the smallest angle of (a, b, c) (see the overload above).
inline double squared_sine_min_angle(const point& a, const point& b, const point& c) noexcept {
  return squared_sine_min_angle(twice_signed_area(a, b, c), squared_distance(b, c),
                                squared_distance(c, a), squared_distance(a, b));
}

/// The angle of the triangle (o, p, q) at o, in degrees (atan2 of the cross and dot products,
/// accurate for small and large angles alike).
inline double angle_at_deg(const point& o, const point& p, const point& q) noexcept {
  const double ux = p.x - o.x, uy = p.y - o.y, vx = q.x - o.x, vy = q.y - o.y;
  return std::atan2(std::abs(ux * vy - uy * vx), ux * vx + uy * vy) * 180.0 / std::numbers::pi;
}

/// The three angles of (a, b, c) in degrees, at a, b and c: the smallest (opposite the
/// shortest edge) and the largest (opposite the longest) by angle_at_deg, the third as 180
/// minus both (two atan2 instead of three: atan2 was a fifth of pdd-mesh's time in the
/// statistics of a finished mesh; the third angle differs from its own atan2 by rounding only).
inline std::array<double, 3> triangle_angles_deg(const point& a, const point& b,
                                                 const point& c) noexcept {
  const std::array<point, 3> p{a, b, c};
  // the squared length of the edge opposite each vertex
  const std::array<double, 3> opposite{squared_distance(b, c), squared_distance(c, a),
                                       squared_distance(a, b)};
  std::size_t lo = 0, hi = 0;
  for (std::size_t i = 1; i < 3; ++i) {
    if (opposite[i] < opposite[lo]) lo = i;
    if (opposite[i] >= opposite[hi]) hi = i;
  }
  if (lo == hi) hi = (lo + 1) % 3; // all three edges of equal length
  const auto at = [&](std::size_t i) { return angle_at_deg(p[i], p[(i + 1) % 3], p[(i + 2) % 3]); };
  std::array<double, 3> angle{};
  angle[lo] = at(lo);
  angle[hi] = at(hi);
  angle[3 - lo - hi] = 180.0 - angle[lo] - angle[hi];
  return angle;
}

/// The smallest angle of (a, b, c) in degrees: the one opposite the shortest edge, with one
/// atan2 instead of three (where two edges tie to rounding, their opposite angles agree to
/// rounding too).
inline double smallest_angle_deg(const point& a, const point& b, const point& c) noexcept {
  const double la = squared_distance(b, c);
  const double lb = squared_distance(c, a);
  const double lc = squared_distance(a, b);
  if (la <= lb && la <= lc) return angle_at_deg(a, b, c);
  return lb <= lc ? angle_at_deg(b, c, a) : angle_at_deg(c, a, b);
}

/// The largest angle of (a, b, c) in degrees: the one opposite the longest edge (one atan2).
inline double largest_angle_deg(const point& a, const point& b, const point& c) noexcept {
  const double la = squared_distance(b, c);
  const double lb = squared_distance(c, a);
  const double lc = squared_distance(a, b);
  if (la >= lb && la >= lc) return angle_at_deg(a, b, c);
  return lb >= lc ? angle_at_deg(b, c, a) : angle_at_deg(c, a, b);
}

/// The cosine of the angle at the corner opposite the edge of squared length `opposite`,
/// between edges of squared lengths `side1` and `side2` (the law of cosines; NaN for a
/// zero-length side). Accurate to a few 1e-8 deg for thin angles: enough to bin angles.
inline double corner_cosine(double opposite, double side1, double side2) noexcept {
  return (side1 + side2 - opposite) / (2.0 * std::sqrt(side1 * side2));
}

/// cos(k deg) for k = 0..180, the bin boundaries of degree_bin.
inline const std::array<double, 181>& degree_cosines() noexcept {
  static const std::array<double, 181> cosines = [] {
    std::array<double, 181> t{};
    for (std::size_t k = 0; k < t.size(); ++k)
      t[k] = std::cos(static_cast<double>(k) * std::numbers::pi / 180.0);
    return t;
  }();
  return cosines;
}

/// The cells of degree_bin's table: 1 - cosine in [0, 2] cut into this many equal cells, each
/// narrower (1.2e-4) than the narrowest degree in cosine (cos 0 - cos 1 deg = 1.5e-4).
constexpr std::size_t degree_cells = 16384;

/// Per cell j, the bin of the cosine 1 - (j - 1) * 2 / degree_cells, one cell above the
/// cell's own top (so that rounding in the cell index can never start above the answer).
inline const std::array<std::uint8_t, degree_cells>& degree_cell_start() noexcept {
  static const std::array<std::uint8_t, degree_cells> start = [] {
    std::array<std::uint8_t, degree_cells> t{};
    const auto& c = degree_cosines();
    for (std::size_t j = 0; j < degree_cells; ++j) {
      const double top = 1.0 - (static_cast<double>(j) - 1.0) * 2.0 / degree_cells;
      std::uint8_t k = 0;
      while (k < 179 && c[k + 1] >= top)
        ++k;
      t[j] = k;
    }
    return t;
  }();
  return start;
}

/// The whole degree an angle of cosine `cosine` lies in, 0..179 (floor of the angle, clamped):
/// the largest k in 1..179 with cos(k deg) >= cosine, else 0; 0 for NaN. No inverse cosine: a
/// table over 1 - cosine gives a k no larger than the answer (a cell is narrower than any
/// degree, and the table starts one cell higher), and at most a few comparisons with cos(k
/// deg) finish it (it had been a binary search of 8 steps, three per triangle in the
/// statistics of a mesh).
inline std::size_t degree_bin(double cosine) noexcept {
  if (std::isnan(cosine)) return 0;
  const auto& c = degree_cosines();
  const double u = (1.0 - cosine) * (degree_cells / 2.0);
  constexpr double last = static_cast<double>(degree_cells - 1);
  // clamped before the conversion (a cosine of -inf gives u = inf)
  const std::size_t j = u <= 0.0 ? 0 : static_cast<std::size_t>(std::min(u, last));
  std::size_t k = degree_cell_start()[j];
  while (k < 179 && c[k + 1] >= cosine)
    ++k;
  return k;
}

/// The triangle of a set with the smallest key, kept with its corners so that its exact
/// measure (an atan2, a circumradius) is taken once at the end rather than for every
/// triangle; the key is a cheap measure monotone in that one (a squared sine for the smallest
/// angle, a cosine for the largest). Ties keep the first offered; join keeps the left one on
/// ties, so a reduction in a fixed order is deterministic. A NaN key (all corners equal)
/// counts as -1, the worst.
struct extreme_triangle {
  double key = std::numeric_limits<double>::infinity();
  std::array<point, 3> corners{};
  bool found = false;

  void offer(double k, const point& a, const point& b, const point& c) noexcept {
    if (std::isnan(k)) k = -1.0;
    if (k < key) {
      key = k;
      corners = {a, b, c};
      found = true;
    }
  }
  void join(const extreme_triangle& o) noexcept {
    if (o.key < key) *this = o;
  }
};

/// Circumradius over shortest edge of (a, b, c) (infinity for a degenerate triangle).
inline double radius_edge_ratio(const point& a, const point& b, const point& c) noexcept {
  const double la = squared_distance(b, c);
  const double lb = squared_distance(c, a);
  const double lc = squared_distance(a, b);
  const double two_area = std::abs(twice_signed_area(a, b, c));
  // R = la lb lc / (4 area) (lengths, not squares) = sqrt(la lb lc) / (2 * two_area).
  const double r = std::sqrt(la) * std::sqrt(lb) * std::sqrt(lc) / (2.0 * two_area);
  return r / std::sqrt(std::min({la, lb, lc}));
}

} // namespace pdd::detail
