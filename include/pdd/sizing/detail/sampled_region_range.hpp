/// \file sampled_region_range.hpp
/// Implementation of pdd::sizing_range over a region for fields without a range(): the grid
/// rule of sampled_range.hpp with the samples taken in the closed region only (grid nodes
/// inside it and points of its boundary), so that the field is never evaluated in a hole or
/// outside the domain. The rule is documented in sizing_range.hpp.
#pragma once

#include <pdd/concepts/sizing_field.hpp>
#include <pdd/errors.hpp>
#include <pdd/sizing/detail/region_grid.hpp>
#include <pdd/sizing/detail/sampled_range.hpp>
#include <pdd/sizing/sizing_region.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace pdd::detail {

/// The smallest value a region evaluation saw and where (for the error message).
struct lowest_sample {
  double value = std::numeric_limits<double>::infinity(); ///< the smallest value
  point at{};                                             ///< where it was taken
  void see(double v, const point& p) {
    if (v < value) *this = {v, p};
  }
};

/// f at p, a point of the closed region. \throws pdd::sizing_error naming p when the value is
/// NaN or <= 0 (the field is not positive on the domain).
template <SizingField F>
double region_value(const F& f, const point& p) {
  const double a = static_cast<double>(f.area_at(p));
  if (!(a > 0.0))
    throw sizing_error("the sizing field is " + std::to_string(a) + " at (" + std::to_string(p.x) +
                       ", " + std::to_string(p.y) +
                       "), a point of the domain; a maximum area must be > 0");
  return a;
}

/// The field's values at the grid's nodes in the region; NaN at the others, which
/// sampled_range's second differences then leave out (a NaN difference counts 0).
template <SizingField F>
sampled_grid sample_region_nodes(const F& f, const region_grid& g, lowest_sample& low) {
  sampled_grid s{
      g.nx, g.ny,
      std::vector<double>((g.nx + 1) * (g.ny + 1), std::numeric_limits<double>::quiet_NaN())};
  for (std::size_t j = 0; j <= g.ny; ++j)
    for (std::size_t i = 0; i <= g.nx; ++i)
      if (g.node_inside(i, j)) {
        const point p = g.node(i, j);
        s.v[j * (g.nx + 1) + i] = region_value(f, p);
        low.see(s.v[j * (g.nx + 1) + i], p);
      }
  return s;
}

/// The smallest and largest sample of cell (i, j): its corners in the region and the boundary
/// points in it; lo = +infinity, hi = 0 when it has none (the cell misses the region).
inline sizing_bounds cell_sample_range(const region_grid& g, const sampled_grid& s,
                                       const std::vector<double>& boundary_values, std::size_t i,
                                       std::size_t j) {
  sizing_bounds r{std::numeric_limits<double>::infinity(), 0.0};
  for (std::size_t c = 0; c < 4; ++c) {
    const std::size_t ni = i + (c & 1), nj = j + (c >> 1);
    if (!g.node_inside(ni, nj)) continue;
    r = {std::min(r.lo, s.at(ni, nj)), std::max(r.hi, s.at(ni, nj))};
  }
  const std::size_t cell = j * g.nx + i;
  for (std::size_t k = g.cell_first[cell]; k < g.cell_first[cell + 1]; ++k) {
    const double v = boundary_values[g.cell_samples[k]];
    r = {std::min(r.lo, v), std::max(r.hi, v)};
  }
  return r;
}

/// Bounds from one region grid: per cell that meets the region, lo = (smallest sample) -
/// margin, hi = (largest sample) + margin, the margin 2 (Dxx + Dyy) / 8 from the second
/// differences of the nodes in the region around it; a cell with an infinite sample has hi =
/// infinity and lo = half its smallest finite sample. lo <= 0 means: refine.
inline sizing_bounds region_grid_bounds(const region_grid& g, const sampled_grid& s,
                                        const std::vector<double>& boundary_values) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  sizing_bounds r{inf, 0.0};
  const cell_curvatures curv = curvatures(s);
  for (std::size_t j = 0; j < g.ny; ++j)
    for (std::size_t i = 0; i < g.nx; ++i) {
      const sizing_bounds c = cell_sample_range(g, s, boundary_values, i, j);
      if (c.hi == 0.0) continue; // no sample: the cell misses the region
      if (std::isinf(c.lo)) {    // F = infinity at every sample: no bound there
        r.hi = inf;
        continue;
      }
      const double m = 2.0 * (curv.dxx[j * g.nx + i] + curv.dyy[j * g.nx + i]) / 8.0;
      r.lo = std::min(r.lo, std::isinf(c.hi) ? 0.5 * c.lo : c.lo - m);
      r.hi = std::max(r.hi, c.hi + m);
    }
  if (r.hi == 0.0) r.hi = inf;
  return r;
}

/// The bounds of f over region r from an n x n region grid.
template <SizingField F>
sizing_bounds region_grid_range(const F& f, const sizing_region& r, std::size_t n,
                                lowest_sample& low) {
  const region_grid g = layout_region_grid(r, n, n);
  const sampled_grid s = sample_region_nodes(f, g, low);
  std::vector<double> boundary_values(g.boundary.size());
  for (std::size_t k = 0; k < g.boundary.size(); ++k) {
    boundary_values[k] = region_value(f, g.boundary[k]);
    low.see(boundary_values[k], g.boundary[k]);
  }
  return region_grid_bounds(g, s, boundary_values);
}

/// The cells a side of the first region grid: as first_grid_cells (sampled_range.hpp), with the
/// 8 x 8 bounds taken over the region. `coarse` receives them when they were taken.
template <SizingField F>
std::size_t first_region_grid_cells(const F& f, const sizing_region& r, std::size_t cells,
                                    double mesh_resolution, sizing_bounds& coarse,
                                    lowest_sample& low) {
  constexpr std::size_t smallest = 8;
  if (!(mesh_resolution > 0.0) || cells <= smallest) return cells;
  coarse = region_grid_range(f, r, smallest, low);
  if (!(coarse.lo > 0.0) || !std::isfinite(coarse.lo)) return cells;
  return mesh_scale_cells(r.box(), coarse.lo, mesh_resolution, cells);
}

/// The error of a region whose lower bound stays <= 0 at the finest grid.
inline sizing_error unbounded_over_region(const pdd::bbox& b, const lowest_sample& low) {
  return sizing_error(
      "the sizing field's minimum over the domain (in [" + std::to_string(b.xmin) + ", " +
      std::to_string(b.xmax) + "] x [" + std::to_string(b.ymin) + ", " + std::to_string(b.ymax) +
      "]) cannot be bounded away from 0 by a 1024 x 1024 grid evaluation (its smallest value "
      "seen: " +
      std::to_string(low.value) + " at (" + std::to_string(low.at.x) + ", " +
      std::to_string(low.at.y) + ")); give the field a range() (BoundedSizingField)");
}

/// pdd::sizing_range over a region for fields without range(): see the rule in
/// sizing_range.hpp. \throws pdd::sizing_error (a value <= 0 or NaN at a point of the region,
/// naming it; no positive lower bound at 1024 cells).
template <SizingField F>
sizing_bounds sampled_region_range(const F& f, const sizing_region& r, std::size_t cells,
                                   double mesh_resolution = 0.0) {
  if (r.empty())
    return {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  const pdd::bbox b = r.box();
  if (!(b.xmax > b.xmin && b.ymax > b.ymin)) // degenerate triangles only: the box is the region
    return sampled_range(f, b, cells, mesh_resolution);
  constexpr std::size_t finest = 1024;
  lowest_sample low;
  sizing_bounds coarse{0.0, 0.0};
  std::size_t n =
      first_region_grid_cells(f, r, std::max<std::size_t>(cells, 2), mesh_resolution, coarse, low);
  if (n == 8 && coarse.lo > 0.0) return coarse; // the mesh-scale grid is the first one
  for (;; n = std::min(n * 4, finest)) {
    const sizing_bounds got = region_grid_range(f, r, n, low);
    if (got.lo > 0.0) return got;
    if (n >= finest) throw unbounded_over_region(b, low);
  }
}

} // namespace pdd::detail
