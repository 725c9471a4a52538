/// \file plan.hpp
/// Implementation of the shielding of small angles (dissertation 8.1): the angles, the length l
/// of Algorithm 8.2 line 5 and the distances |ab'| of eq. 8.1.
#pragma once

#include <pdd/errors.hpp>
#include <pdd/core/point.hpp>
#include <pdd/geometry/properties.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace pdd::detail {

/// The angle below which an input angle is shielded (Ruppert's algorithm needs >= 60 deg).
inline constexpr double shield_threshold_deg = 60.0;

/// Per loop vertex (the loop walked with the domain on its left): the domain-side angle in
/// degrees when it is < 60 deg and eligible[i], else 0. Complexity O(n).
inline std::vector<double> shield_angles(const std::vector<point>& loop,
                                         const std::vector<char>& eligible) {
  const std::size_t n = loop.size();
  std::vector<double> theta(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    if (!eligible[i]) continue;
    const double a = ccw_angle_deg(loop[i], loop[(i + 1) % n], loop[(i + n - 1) % n]);
    if (a < shield_threshold_deg) theta[i] = a;
  }
  return theta;
}

/// l_i of Algorithm 8.2 line 5 (eq. 8.6): min over the small angles theta of
/// {(1 + 2 sin(theta/2)) sqrt(2 A sin theta), sqrt(A / sqrt 2)} and lfs_min (A = area_bound;
/// the area terms are left out when A is infinite). Complexity O(n).
inline double shield_length(const std::vector<std::vector<double>>& theta, double lfs,
                            double area_bound) {
  double l = lfs;
  if (std::isfinite(area_bound)) {
    for (const auto& loop : theta)
      for (const double t : loop) {
        if (t <= 0.0) continue;
        const double r = t * std::numbers::pi / 180.0;
        l = std::min(l,
                     (1.0 + 2.0 * std::sin(r / 2.0)) * std::sqrt(2.0 * area_bound * std::sin(r)));
      }
    l = std::min(l, std::sqrt(area_bound / std::numbers::sqrt2));
    // At equality the shielded triangle's area is A exactly; computed coordinates could leave
    // it an ulp above. One part in 1e9 shorter keeps area <= A after rounding.
    l *= 1.0 - 1e-9;
  }
  return l;
}

/// |ab'| = |ac'| = l / (2 sin(theta/2) (cos(theta/2) + sin theta)) (eq. 8.1), theta in degrees.
inline double shield_distance(double theta_deg, double l) {
  const double r = theta_deg * std::numbers::pi / 180.0;
  return l / (2.0 * std::sin(r / 2.0) * (std::cos(r / 2.0) + std::sin(r)));
}

/// The point at distance `dist` from a towards b: a + (b - a) dist / |ab|.
inline point shield_point(point a, point b, double dist) {
  const double t = dist / std::hypot(b.x - a.x, b.y - a.y);
  return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t};
}

/// Per loop vertex: |ab'| (eq. 8.1) for a shielded vertex, 0 otherwise.
/// \throws pdd::geometry_error naming the vertices (ids[i]) when the shield points of an edge
/// would not leave a gap between them (Lemma 23 (ii), (iv) exclude it for l <= lfs_min).
inline std::vector<double> shield_distances(const std::vector<point>& loop,
                                            const std::vector<double>& theta, double l,
                                            const std::vector<index_t>& ids) {
  const std::size_t n = loop.size();
  std::vector<double> dist(n, 0.0);
  for (std::size_t i = 0; i < n; ++i)
    if (theta[i] > 0.0) dist[i] = shield_distance(theta[i], l);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    if (dist[i] == 0.0 && dist[j] == 0.0) continue;
    const double len = std::hypot(loop[j].x - loop[i].x, loop[j].y - loop[i].y);
    if (!(dist[i] + dist[j] < len))
      throw geometry_error(
          "cannot shield the small angles at vertices " + std::to_string(ids[i]) + " and " +
              std::to_string(ids[j]) +
              ": the shield points do not fit on their segment (l = " + std::to_string(l) + ")",
          {ids[i], ids[j]});
  }
  return dist;
}

} // namespace pdd::detail
