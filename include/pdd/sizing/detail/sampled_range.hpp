/// \file sampled_range.hpp
/// Implementation of pdd::sizing_range for fields without a range(): bounds from a grid
/// evaluation with a curvature margin (the safety rule is documented in sizing_range.hpp).
#pragma once

#include <pdd/concepts/sizing_field.hpp>
#include <pdd/errors.hpp>
#include <pdd/sizing/detail/region_grid.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>
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
      const point p = grid_node(b, nx, ny, i, j);
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

/// The largest |second differences| around every cell: for cell (i, j), Dxx and Dyy are the
/// maxima over the nodes of the cell and of its 8 neighbours (nodes i-1..i+2, j-1..j+2, clipped
/// to the grid). Each node's second differences are taken once and the 4 x 4 window maxima
/// are separable (rows, then columns): O(nodes) instead of 32 differences per cell.
struct cell_curvatures {
  std::vector<double> dxx, dyy; ///< per cell, row-major (max(nx, 1) cells a row)
};

/// The windowed maximum along one axis: out[c] = max of v[c-1 .. c+2] clipped to [0, n].
inline void window_max(const double* v, std::size_t n, std::size_t stride, std::size_t cells,
                       double* out, std::size_t out_stride) {
  for (std::size_t c = 0; c < cells; ++c) {
    double m = 0.0;
    for (std::size_t k = c > 0 ? c - 1 : 0; k <= std::min(c + 2, n); ++k)
      m = std::max(m, v[k * stride]);
    out[c * out_stride] = m;
  }
}

inline cell_curvatures curvatures(const sampled_grid& g) {
  const std::size_t nodes_x = g.nx + 1, nodes_y = g.ny + 1;
  const std::size_t cx = std::max<std::size_t>(g.nx, 1), cy = std::max<std::size_t>(g.ny, 1);
  std::vector<double> sx(nodes_x * nodes_y), sy(nodes_x * nodes_y);
  for (std::size_t j = 0; j < nodes_y; ++j)
    for (std::size_t i = 0; i < nodes_x; ++i) {
      sx[j * nodes_x + i] = second_difference_x(g, i, j);
      sy[j * nodes_x + i] = second_difference_y(g, i, j);
    }
  cell_curvatures c{std::vector<double>(cx * cy), std::vector<double>(cx * cy)};
  std::vector<double> rows(cx * nodes_y); // per node row, the window maximum along x
  for (auto [node, cell] : {std::pair{&sx, &c.dxx}, std::pair{&sy, &c.dyy}}) {
    for (std::size_t j = 0; j < nodes_y; ++j)
      window_max(node->data() + j * nodes_x, g.nx, 1, cx, rows.data() + j * cx, 1);
    for (std::size_t i = 0; i < cx; ++i)
      window_max(rows.data() + i, g.ny, cx, cy, cell->data() + i, cx);
  }
  return c;
}

/// Bounds from one grid: per cell, lo = (smallest corner) - margin, hi = (largest corner) +
/// margin; a cell with an infinite corner has hi = infinity and lo = half its smallest finite
/// corner. Returns lo <= 0 when the margin swallows the values (the caller refines).
inline sizing_bounds grid_bounds(const sampled_grid& g) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  sizing_bounds r{inf, 0.0};
  const std::size_t cx = std::max<std::size_t>(g.nx, 1), cy = std::max<std::size_t>(g.ny, 1);
  const cell_curvatures curv = curvatures(g);
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
      // the curvature margin 2 (Dxx + Dyy) / 8 (see sizing_range.hpp)
      const double m = 2.0 * (curv.dxx[j * cx + i] + curv.dyy[j * cx + i]) / 8.0;
      r.lo = std::min(r.lo, std::isinf(hi) ? 0.5 * lo : lo - m);
      r.hi = std::max(r.hi, hi + m);
    }
  if (r.hi == 0.0) r.hi = inf;
  return r;
}

/// The mesh-scale cell count: ceil(mesh_resolution * longer side of b / sqrt(lo)) within
/// [8, cells] (sizing_range_options::mesh_resolution).
inline std::size_t mesh_scale_cells(const pdd::bbox& b, double lo, double mesh_resolution,
                                    std::size_t cells) {
  const double side = std::max(b.xmax - b.xmin, b.ymax - b.ymin);
  const double want = std::ceil(mesh_resolution * side / std::sqrt(lo));
  return static_cast<std::size_t>(std::clamp(want, 8.0, static_cast<double>(cells)));
}

/// The cells a side of sampled_range's first grid: `cells`, or with mesh_resolution > 0 the
/// mesh-scale count ceil(mesh_resolution * longer side / sqrt(lo)) within [8, cells], lo the
/// lower bound of a first 8 x 8 grid (no coarsening when that grid gives no positive, finite
/// bound). `coarse` receives the 8 x 8 bounds when they were taken.
template <SizingField F>
std::size_t first_grid_cells(const F& f, const pdd::bbox& b, std::size_t cells,
                             double mesh_resolution, sizing_bounds& coarse) {
  constexpr std::size_t smallest = 8;
  if (!(mesh_resolution > 0.0) || cells <= smallest) return cells;
  coarse = grid_bounds(
      sample_field(f, b, b.xmax > b.xmin ? smallest : 0, b.ymax > b.ymin ? smallest : 0));
  if (!(coarse.lo > 0.0) || !std::isfinite(coarse.lo)) return cells;
  return mesh_scale_cells(b, coarse.lo, mesh_resolution, cells);
}

/// pdd::sizing_range for fields without range(): see the rule in sizing_range.hpp.
/// \throws pdd::sizing_error (a non-positive value; no positive lower bound at 1024 cells).
template <SizingField F>
sizing_bounds sampled_range(const F& f, const pdd::bbox& b, std::size_t cells,
                            double mesh_resolution = 0.0) {
  if (b.empty())
    return {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  constexpr std::size_t finest = 1024;
  sizing_bounds coarse{0.0, 0.0};
  std::size_t n = first_grid_cells(f, b, std::max<std::size_t>(cells, 2), mesh_resolution, coarse);
  if (n == 8 && coarse.lo > 0.0) return coarse; // the mesh-scale grid is the first one
  for (;; n = std::min(n * 4, finest)) {
    const std::size_t nx = b.xmax > b.xmin ? n : 0, ny = b.ymax > b.ymin ? n : 0;
    const sizing_bounds r = grid_bounds(sample_field(f, b, nx, ny));
    if (r.lo > 0.0) return r;
    if (n >= finest)
      throw sizing_error("the sizing field's minimum over [" + std::to_string(b.xmin) + ", " +
                         std::to_string(b.xmax) + "] x [" + std::to_string(b.ymin) + ", " +
                         std::to_string(b.ymax) +
                         "] cannot be bounded away from 0 by a 1024 x 1024 grid evaluation; "
                         "give the field a range() (BoundedSizingField)");
  }
}

} // namespace pdd::detail
