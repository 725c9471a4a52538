/// \file sizing_field.hpp
/// The SizingField and BoundedSizingField concepts, and pdd::sizing_bounds.
///
/// A SizingField tells the largest triangle area allowed at a point of the plane.
///
/// Requirements: for `const F f` and `pdd::point p`, `f.area_at(p)` is convertible to double.
/// Semantics: the value is > 0 (infinity allowed: no bound there); f is const, thread-safe
/// (area_at may be called from many threads at once) and copyable. A triangle is too large
/// when its area exceeds area_at at its centroid.
///
/// BoundedSizingField refines SizingField for the graded method (dissertation 7.3-7.5, m(D)
/// and M(D)): `f.range(box)` returns pdd::sizing_bounds {lo, hi} with
/// lo <= f.area_at(p) <= hi for every p in the closed box. `lo` must be a TRUE lower bound
/// (the decoupling parameter k_i of Proposition 20 comes from it: an overestimate would let
/// the kernel split interface pieces); `hi` an upper bound. Both may be loose (e.g. taken
/// over the nodes of a background mesh around the box). A field that is not bounded still
/// works everywhere through pdd::sizing_range, which then evaluates it on a grid (see
/// sizing_range.hpp for the safety rule).
///
/// Models: pdd::uniform_sizing, pdd::analytic_sizing (bounded when given a range function),
/// pdd::expression_sizing, pdd::background_mesh_sizing, pdd::grid_sizing,
/// pdd::regional_sizing, pdd::min_sizing, pdd::any_sizing.
#pragma once

#include <pdd/core/bbox.hpp>
#include <pdd/core/point.hpp>

#include <concepts>

namespace pdd {

/// Bounds of a sizing field over a region: lo <= F(p) <= hi for every p of the region.
/// Empty regions (or regions where F is unbounded) give lo = hi = +infinity.
struct sizing_bounds {
  double lo = 0.0; ///< m(D): a true lower bound
  double hi = 0.0; ///< M(D): an upper bound
};

template <class F>
concept SizingField = std::copy_constructible<F> && requires(const F& f, const point& p) {
  { f.area_at(p) } -> std::convertible_to<double>;
};

template <class F>
concept BoundedSizingField = SizingField<F> && requires(const F& f, const bbox& b) {
  { f.range(b) } -> std::convertible_to<sizing_bounds>;
};

} // namespace pdd
