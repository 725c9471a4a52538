/// \file analytic.hpp
/// pdd::analytic_sizing: a SizingField from any callable double(point).
#pragma once

#include <pdd/concepts/sizing_field.hpp>

#include <concepts>
#include <utility>

namespace pdd {

/// Models SizingField by calling `f(p)`. \tparam Fn copyable callable `double(pdd::point)`;
/// it must be thread-safe (called concurrently) and return values > 0.
template <class Fn>
  requires std::copy_constructible<Fn> && std::invocable<const Fn&, point>
struct analytic_sizing {
  Fn fn;
  double area_at(const point& p) const { return static_cast<double>(fn(p)); }
};
template <class Fn>
analytic_sizing(Fn) -> analytic_sizing<Fn>;

static_assert(SizingField<analytic_sizing<double (*)(point)>>);

} // namespace pdd
