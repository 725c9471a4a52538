/// \file sampled_range.hpp
/// Implementation of pdd::sizing_range for fields without a range(): bounds from a grid
/// evaluation with a curvature margin (the safety rule is documented in sizing_range.hpp).
#pragma once

#include <pdd/concepts/sizing_field.hpp>
#include <pdd/errors.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace pdd::detail {

/// Field values on an (nx+1) x (ny+1) node grid over a box, row-major (y rows).
struct sampled_grid {
  std::size_t nx = 0, ny = 0;
  std::vector<double> v;
  double at(std::size_t i, std::size_t j) const { return v[j * (nx + 1) + i]; }
};

/// Evaluates f at the grid nodes; \throws pdd::sizing_error at a NaN or non-positive value.
template <SizingField F>
sampled_grid sample_field(const F& f, const pdd::bbox& b, std::size_t nx, std::size_t ny) {
  sampled_grid g{nx, ny, std::vector<double>((nx + 1) * (ny + 1))};
  for (std::size_t j = 0; j <= ny; ++j)
    for (std::size_t i = 0; i <= nx; ++i) {
      const point p{nx ? b.xmin + (b.xmax - b.xmin) * static_cast<double>(i) / nx : b.xmin,
                    ny ? b.ymin + (b.ymax - b.ymin) * static_cast<double>(j) / ny : b.ymin};
      const double a = static_cast<double>(f.area_at(p));
      if (!(a > 0.0))
        throw sizing_error("the sizing field is " + std::to_string(a) + " at (" +
                           std::to_string(p.x) + ", " + std::to_string(p.y) +
                           "); a maximum area must be > 0");
      g.v[j * (nx + 1) + i] = a;
    }
  return g;
}

/// |second difference| along x at node (i, j), taken at the nearest node with two neighbours
/// (0 when the grid has fewer than 2 cells along x). Infinite values give 0 (no curvature
/// information; infinite corners are handled by the caller).
inline double second_difference_x(const sampled_grid& g, std::size_t i, std::size_t j) {
  if (g.nx < 2) return 0.0;
  const std::size_t c = std::clamp<std::size_t>(i, 1, g.nx - 1);
  const double d = g.at(c - 1, j) - 2.0 * g.at(c, j) + g.at(c + 1, j);
  return std::isfinite(d) ? std::abs(d) : 0.0;
}
inline double second_difference_y(const sampled_grid& g, std::size_t i, std::size_t j) {
  if (g.ny < 2) return 0.0;
  const std::size_t c = std::clamp<std::size_t>(j, 1, g.ny - 1);
  const double d = g.at(i, c - 1) - 2.0 * g.at(i, c) + g.at(i, c + 1);
  return std::isfinite(d) ? std::abs(d) : 0.0;
}

/// The curvature margin of cell (i, j): 2 x (Dxx + Dyy) / 8, with Dxx, Dyy the largest
/// |second differences| at the nodes of the cell and of its 8 neighbours.
inline double cell_margin(const sampled_grid& g, std::size_t i, std::size_t j) {
  double dxx = 0.0, dyy = 0.0;
  const std::size_t i0 = i > 0 ? i - 1 : 0, j0 = j > 0 ? j - 1 : 0;
  for (std::size_t jj = j0; jj <= std::min(j + 2, g.ny); ++jj)
    for (std::size_t ii = i0; ii <= std::min(i + 2, g.nx); ++ii) {
      dxx = std::max(dxx, second_difference_x(g, ii, jj));
      dyy = std::max(dyy, second_difference_y(g, ii, jj));
    }
  return 2.0 * (dxx + dyy) / 8.0;
}

/// Bounds from one grid: per cell, lo = (smallest corner) - margin, hi = (largest corner) +
/// margin; a cell with an infinite corner has hi = infinity and lo = half its smallest finite
/// corner. Returns lo <= 0 when the margin swallows the values (the caller refines).
inline sizing_bounds grid_bounds(const sampled_grid& g) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  sizing_bounds r{inf, 0.0};
  const std::size_t cx = std::max<std::size_t>(g.nx, 1), cy = std::max<std::size_t>(g.ny, 1);
  for (std::size_t j = 0; j < cy; ++j)
    for (std::size_t i = 0; i < cx; ++i) {
      double lo = inf, hi = 0.0;
      for (std::size_t c = 0; c < 4; ++c) {
        const double v = g.at(std::min(i + (c & 1), g.nx), std::min(j + (c >> 1), g.ny));
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
      if (std::isinf(lo)) { // F = infinity at every corner: no bound there
        r.hi = inf;
        continue;
      }
      const double m = cell_margin(g, i, j);
      r.lo = std::min(r.lo, std::isinf(hi) ? 0.5 * lo : lo - m);
      r.hi = std::max(r.hi, hi + m);
    }
  if (r.hi == 0.0) r.hi = inf;
  return r;
}

/// pdd::sizing_range for fields without range(): see the rule in sizing_range.hpp.
/// \throws pdd::sizing_error (a non-positive value; no positive lower bound at 1024 cells).
template <SizingField F>
sizing_bounds sampled_range(const F& f, const pdd::bbox& b, std::size_t cells) {
  if (b.empty())
    return {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  for (std::size_t n = std::max<std::size_t>(cells, 2);; n *= 4) {
    const std::size_t nx = b.xmax > b.xmin ? n : 0, ny = b.ymax > b.ymin ? n : 0;
    const sizing_bounds r = grid_bounds(sample_field(f, b, nx, ny));
    if (r.lo > 0.0) return r;
    if (n >= 1024)
      throw sizing_error("the sizing field's minimum over [" + std::to_string(b.xmin) + ", " +
                         std::to_string(b.xmax) + "] x [" + std::to_string(b.ymin) + ", " +
                         std::to_string(b.ymax) +
                         "] cannot be bounded away from 0 by a 1024 x 1024 grid evaluation; "
                         "give the field a range() (BoundedSizingField)");
  }
}

} // namespace pdd::detail
