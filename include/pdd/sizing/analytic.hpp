/// \file analytic.hpp
/// pdd::analytic_sizing: a SizingField from any callable double(point), optionally with the
/// exact range of the callable over a box.
#pragma once

#include <pdd/concepts/sizing_field.hpp>

#include <concepts>
#include <type_traits>
#include <utility>

namespace pdd {

/// No range function: pdd::sizing_range evaluates the callable on a grid.
struct no_range {};

/// Models SizingField by calling `fn(p)`; with a range function `range_fn(bbox)` returning
/// pdd::sizing_bounds (a TRUE lower bound and an upper bound of fn over the box) it models
/// BoundedSizingField, otherwise pdd::sizing_range bounds it by its grid rule.
/// \tparam Fn copyable callable `double(pdd::point)`: thread-safe, values > 0.
/// \tparam R pdd::no_range, or a copyable callable `sizing_bounds(const bbox&)`.
template <class Fn, class R = no_range>
requires std::copy_constructible<Fn> && std::invocable<const Fn&, point>
struct analytic_sizing {
  /// The area bound at a point: fn(p) > 0 (infinity: no bound there).
  Fn fn;
  /// The bounds of fn over a box (pdd::no_range, the default: none; pdd::sizing_range then
  /// samples fn on a grid).
  [[no_unique_address]] R range_fn{};

  /// The largest triangle area allowed at p: fn(p), converted to double.
  double area_at(const point& p) const { return static_cast<double>(fn(p)); }
  /// range_fn(b): bounds of fn over the closed box b (only with a range function).
  sizing_bounds range(const bbox& b) const requires std::invocable<const R&, const bbox&> {
    return range_fn(b);
  }
  /// "analytic": the field's name in reports (any_sizing::kind, min_sizing::kind).
  static constexpr const char* kind() noexcept { return "analytic"; }
};
/// Deduces analytic_sizing<Fn> (no range function) from `analytic_sizing{fn}`.
template <class Fn>
analytic_sizing(Fn) -> analytic_sizing<Fn>;
/// Deduces analytic_sizing<Fn, R> from `analytic_sizing{fn, range_fn}`.
template <class Fn, class R>
analytic_sizing(Fn, R) -> analytic_sizing<Fn, R>;

static_assert(SizingField<analytic_sizing<double (*)(point)>>);
static_assert(!BoundedSizingField<analytic_sizing<double (*)(point)>>);
static_assert(
    BoundedSizingField<analytic_sizing<double (*)(point), sizing_bounds (*)(const bbox&)>>);

} // namespace pdd
