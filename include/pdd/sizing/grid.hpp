/// \file grid.hpp
/// pdd::grid_sizing: a sizing field on a structured grid with uniform spacing, interpolated
/// bilinearly (Gmsh's structured field, JIGSAW's hfun on a grid).
#pragma once

#include <pdd/concepts/sizing_field.hpp>
#include <pdd/errors.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace pdd {

/// Models BoundedSizingField on nx x ny nodes (x0 + i dx, y0 + j dy), i < nx, j < ny, values
/// row by row (values[j * nx + i]). Inside a cell F is the bilinear interpolation of its
/// four corner values; outside the grid F is infinity (no bound). range(box) is exact over
/// the cells the box meets (a bilinear function takes its extremes at the corners), so lo is
/// a true lower bound; hi is infinity when the box reaches outside the grid.
/// Thread-safety: const and shared; copies share the values.
class grid_sizing {
public:
  /// \throws pdd::sizing_error: nx or ny < 2, dx or dy not finite and > 0, a value count that
  /// does not match, or a value not finite and > 0 (naming its node i, j).
  grid_sizing(point origin, double dx, double dy, std::size_t nx, std::size_t ny,
              std::vector<double> values)
      : d_(std::make_shared<data>(data{origin, dx, dy, nx, ny, std::move(values)})) {
    if (nx < 2 || ny < 2)
      throw sizing_error("area grid: at least 2 x 2 nodes are needed, got " + std::to_string(nx) +
                         " x " + std::to_string(ny));
    if (!(dx > 0.0 && std::isfinite(dx) && dy > 0.0 && std::isfinite(dy)))
      throw sizing_error("area grid: the spacing must be finite and > 0, got " +
                         std::to_string(dx) + " x " + std::to_string(dy));
    if (d_->values.size() != nx * ny)
      throw sizing_error("area grid: " + std::to_string(d_->values.size()) + " values for " +
                         std::to_string(nx) + " x " + std::to_string(ny) + " nodes");
    for (std::size_t k = 0; k < d_->values.size(); ++k)
      if (!(d_->values[k] > 0.0 && std::isfinite(d_->values[k])))
        throw sizing_error("area grid: the value at node (" + std::to_string(k % nx) + ", " +
                           std::to_string(k / nx) + ") is " + std::to_string(d_->values[k]) +
                           "; it must be finite and > 0");
  }

  /// F(p): the bilinear interpolation in the cell that holds p; infinity (no bound) outside
  /// the grid.
  double area_at(const point& p) const {
    const data& d = *d_;
    const double u = (p.x - d.origin.x) / d.dx, v = (p.y - d.origin.y) / d.dy;
    if (!(u >= 0.0 && v >= 0.0 && u <= double(d.nx - 1) && v <= double(d.ny - 1)))
      return std::numeric_limits<double>::infinity();
    const std::size_t i = std::min(static_cast<std::size_t>(u), d.nx - 2);
    const std::size_t j = std::min(static_cast<std::size_t>(v), d.ny - 2);
    const double s = u - double(i), t = v - double(j);
    const double r = (1 - s) * (1 - t) * at(i, j) + s * (1 - t) * at(i + 1, j) +
                     (1 - s) * t * at(i, j + 1) + s * t * at(i + 1, j + 1);
    const double lo = std::min({at(i, j), at(i + 1, j), at(i, j + 1), at(i + 1, j + 1)});
    const double hi = std::max({at(i, j), at(i + 1, j), at(i, j + 1), at(i + 1, j + 1)});
    return std::clamp(r, lo, hi);
  }

  /// {min, max} of the node values of the cells the closed box b meets (exact); hi is
  /// infinity when b reaches outside the grid, and both are infinity for an empty box or one
  /// that misses the grid.
  sizing_bounds range(const bbox& b) const {
    constexpr double inf = std::numeric_limits<double>::infinity();
    const data& d = *d_;
    if (b.empty()) return {inf, inf};
    const double u0 = (b.xmin - d.origin.x) / d.dx, u1 = (b.xmax - d.origin.x) / d.dx;
    const double v0 = (b.ymin - d.origin.y) / d.dy, v1 = (b.ymax - d.origin.y) / d.dy;
    const double umax = double(d.nx - 1), vmax = double(d.ny - 1);
    if (u1 < 0.0 || v1 < 0.0 || u0 > umax || v0 > vmax) return {inf, inf};
    const bool inside = u0 >= 0.0 && v0 >= 0.0 && u1 <= umax && v1 <= vmax;
    // nodes of every cell the box meets: floor of the low end to ceil of the high end
    const auto node = [](double w, double top) {
      return static_cast<std::size_t>(std::clamp(w, 0.0, top));
    };
    const std::size_t i0 = node(std::floor(u0), umax), i1 = node(std::ceil(u1), umax);
    const std::size_t j0 = node(std::floor(v0), vmax), j1 = node(std::ceil(v1), vmax);
    sizing_bounds r{inf, 0.0};
    for (std::size_t j = j0; j <= j1; ++j)
      for (std::size_t i = i0; i <= i1; ++i) {
        r.lo = std::min(r.lo, at(i, j));
        r.hi = std::max(r.hi, at(i, j));
      }
    if (!inside) r.hi = inf;
    return r;
  }

  /// "grid": the field's name in reports (any_sizing::kind, min_sizing::kind).
  static constexpr const char* kind() noexcept { return "grid"; }
  /// The number of nodes along x (>= 2).
  std::size_t nx() const noexcept { return d_->nx; }
  /// The number of nodes along y (>= 2).
  std::size_t ny() const noexcept { return d_->ny; }

private:
  struct data {
    point origin;
    double dx, dy;
    std::size_t nx, ny;
    std::vector<double> values;
  };
  double at(std::size_t i, std::size_t j) const { return d_->values[j * d_->nx + i]; }
  std::shared_ptr<const data> d_;
};
static_assert(BoundedSizingField<grid_sizing>);

} // namespace pdd
