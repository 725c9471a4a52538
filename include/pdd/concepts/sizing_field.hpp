/// \file sizing_field.hpp
/// The SizingField concept.
///
/// A SizingField tells the largest triangle area allowed at a point of the plane.
///
/// Requirements: for `const F f` and `pdd::point p`, `f.area_at(p)` is convertible to double.
/// Semantics: the value is > 0 (infinity allowed: no bound there); f is const, thread-safe
/// (area_at may be called from many threads at once) and copyable. A triangle is too large
/// when its area exceeds area_at at its centroid.
/// Models: pdd::uniform_sizing, pdd::analytic_sizing.
#pragma once

#include <pdd/core/point.hpp>

#include <concepts>

namespace pdd {

template <class F>
concept SizingField = std::copy_constructible<F> && requires(const F& f, const point& p) {
  { f.area_at(p) } -> std::convertible_to<double>;
};

} // namespace pdd
