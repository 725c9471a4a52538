/// \file inverse_area_integral.hpp
/// pdd::inverse_area_integral: the integral of 1 / F over a domain, the expected triangle
/// count of a graded mesh up to the mean-area factor (dissertation Algorithm 7.2: expected
/// elements of a subdomain = integral of 1 / (0.656 F)).
#pragma once

#include <pdd/concepts/sizing_field.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/geometry/domain_faces.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace pdd {

/// Integral of 1 / min(max_area, F(p)) over the triangles (vertex ids into `vertices`) of a
/// triangulated domain: each triangle is cut into n^2 similar pieces (n chosen so that about
/// `samples` pieces cover the domain, at least 1 per triangle) and each piece contributes
/// its area / min(max_area, F(centroid)) (the midpoint rule). Where the bound is infinite the
/// contribution is 0. Deterministic; an estimate (its error shrinks with `samples`), not a
/// bound. \tparam S a SizingField. Complexity O(triangles + samples) evaluations of F.
template <SizingField S>
double inverse_area_integral(const std::vector<point>& vertices,
                             const std::vector<domain_triangle>& triangles, double max_area,
                             const S& sizing, std::size_t samples = 1 << 16) {
  if (triangles.empty()) return 0.0;
  const auto n = static_cast<std::size_t>(
      std::max(1.0, std::floor(std::sqrt(static_cast<double>(samples) / triangles.size()))));
  double sum = 0.0;
  for (const domain_triangle& tri : triangles) {
    const point a = vertices[tri.vertices[0]], b = vertices[tri.vertices[1]],
                c = vertices[tri.vertices[2]];
    const double ux = (b.x - a.x) / n, uy = (b.y - a.y) / n;
    const double vx = (c.x - a.x) / n, vy = (c.y - a.y) / n;
    const double piece = std::abs(ux * vy - uy * vx) / 2.0;
    // pieces of the n x n subdivision: upward (i, j) with i + j < n, downward with i + j < n-1
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; i + j < n; ++j)
        for (int down = 0; down < 2; ++down) {
          if (down && i + j + 1 >= n) continue;
          const double s = i + (down ? 2.0 : 1.0) / 3.0, t = j + (down ? 2.0 : 1.0) / 3.0;
          const point p{a.x + s * ux + t * vx, a.y + s * uy + t * vy};
          const double bound = std::min(max_area, static_cast<double>(sizing.area_at(p)));
          if (std::isfinite(bound)) sum += piece / bound;
        }
  }
  return sum;
}

/// The integral above over the domain of g (the triangles of pdd::domain_faces by g.rule).
/// \throws pdd::geometry_error as pdd::domain_faces. Complexity O(n log n + samples).
template <SizingField S>
double inverse_area_integral(const pslg& g, double max_area, const S& sizing,
                             std::size_t samples = 1 << 16) {
  return inverse_area_integral(g.vertices, domain_faces(g).triangles(), max_area, sizing, samples);
}

} // namespace pdd
