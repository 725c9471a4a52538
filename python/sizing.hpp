// Sizing fields from Python for pdd.mesh: a callable f(x, y) -> area, called with the GIL
// held, and a numpy grid of areas interpolated bilinearly.
#pragma once

#include "arrays.hpp"

#include <pdd/concepts/sizing_field.hpp>
#include <pdd/core/point.hpp>

#include <pybind11/pybind11.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace pdd::python {

/// A Python callable f(x, y) -> area as a SizingField. The kernel runs with the GIL released;
/// every area_at takes the GIL for the call (one kernel thread calls it: pdd.mesh meshes the
/// whole domain at once with a sizing field, so no thread waits on another for it). A Python
/// exception or a value that is not a finite number > 0 throws bad_argument naming the point.
struct callable_sizing {
  std::shared_ptr<py::function> fn; // shared: SizingField models are copied

  double area_at(const point& p) const {
    py::gil_scoped_acquire gil;
    double v = 0.0;
    try {
      v = (*fn)(p.x, p.y).cast<double>();
    } catch (py::error_already_set& e) {
      const std::string msg = e.what();
      throw bad_argument("the sizing function raised at (" + std::to_string(p.x) + ", " +
                         std::to_string(p.y) + "): " + msg);
    } catch (const py::cast_error&) {
      throw bad_argument("the sizing function must return a number");
    }
    if (!(std::isfinite(v) && v > 0.0) && !(std::isinf(v) && v > 0.0))
      throw bad_argument("the sizing function returned " + std::to_string(v) + " at (" +
                         std::to_string(p.x) + ", " + std::to_string(p.y) + "); areas must be > 0");
    return v;
  }
};
static_assert(SizingField<callable_sizing>);

/// A (ny, nx) grid of areas over the box [x0, x1] x [y0, y1] (row j at y0 + j (y1 - y0) /
/// (ny - 1)), bilinear between the nodes and clamped to the box outside it.
struct grid_sizing {
  std::shared_ptr<const std::vector<double>> areas;
  std::size_t nx = 0, ny = 0;
  double x0 = 0, y0 = 0, x1 = 1, y1 = 1;

  double area_at(const point& p) const {
    const auto coord = [](double v, double lo, double hi, std::size_t n, std::size_t& i) {
      const double t = std::clamp((v - lo) / (hi - lo), 0.0, 1.0) * static_cast<double>(n - 1);
      i = std::min(static_cast<std::size_t>(t), n - 2);
      return t - static_cast<double>(i);
    };
    std::size_t i = 0, j = 0;
    const double s = coord(p.x, x0, x1, nx, i), t = coord(p.y, y0, y1, ny, j);
    const auto a = [this](std::size_t r, std::size_t c) { return (*areas)[r * nx + c]; };
    return (1 - t) * ((1 - s) * a(j, i) + s * a(j, i + 1)) +
           t * ((1 - s) * a(j + 1, i) + s * a(j + 1, i + 1));
  }
};
static_assert(SizingField<grid_sizing>);

/// A grid_sizing from a 2-D array (at least 2 x 2, every value finite and > 0) over `bounds`
/// (x0, y0, x1, y1) or, when None, the bounding box of `vertices`.
inline grid_sizing make_grid_sizing(const py::handle& grid, const py::handle& bounds,
                                    const std::vector<point>& vertices) {
  auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(grid);
  if (!a || a.ndim() != 2 || a.shape(0) < 2 || a.shape(1) < 2)
    throw bad_argument("a sizing grid must be a 2-D array of at least 2 x 2 areas");
  grid_sizing g;
  g.ny = static_cast<std::size_t>(a.shape(0));
  g.nx = static_cast<std::size_t>(a.shape(1));
  auto v = std::make_shared<std::vector<double>>(a.data(), a.data() + g.nx * g.ny);
  for (const double x : *v)
    if (!(std::isfinite(x) && x > 0.0))
      throw bad_argument("sizing grid values must be finite and > 0, found " + std::to_string(x));
  g.areas = std::move(v);
  if (bounds.is_none()) {
    g.x0 = g.y0 = INFINITY;
    g.x1 = g.y1 = -INFINITY;
    for (const point& p : vertices) {
      g.x0 = std::min(g.x0, p.x), g.x1 = std::max(g.x1, p.x);
      g.y0 = std::min(g.y0, p.y), g.y1 = std::max(g.y1, p.y);
    }
  } else {
    const auto b = bounds.cast<std::vector<double>>();
    if (b.size() != 4) throw bad_argument("sizing_bounds must be (x0, y0, x1, y1)");
    g.x0 = b[0], g.y0 = b[1], g.x1 = b[2], g.y1 = b[3];
  }
  if (!(g.x1 > g.x0 && g.y1 > g.y0))
    throw bad_argument("sizing_bounds must satisfy x0 < x1 and y0 < y1");
  return g;
}

} // namespace pdd::python
