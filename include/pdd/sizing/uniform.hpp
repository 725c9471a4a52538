/// \file uniform.hpp
/// pdd::uniform_sizing: the same area bound everywhere.
#pragma once

#include <pdd/concepts/sizing_field.hpp>

#include <limits>

namespace pdd {

/// Models BoundedSizingField with one area bound everywhere (infinity: no bound); its range
/// over any non-empty box is exact.
struct uniform_sizing {
  /// The largest triangle area allowed anywhere, > 0; infinity (the default): no bound.
  double area = std::numeric_limits<double>::infinity();
  /// `area`, whatever the point.
  double area_at(const point&) const noexcept { return area; }
  /// {area, area} over a non-empty box (exact); {infinity, infinity} over an empty one.
  sizing_bounds range(const bbox& b) const noexcept {
    if (b.empty())
      return {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    return {area, area};
  }
  /// "uniform": the field's name in reports (any_sizing::kind, min_sizing::kind).
  static constexpr const char* kind() noexcept { return "uniform"; }
};
static_assert(BoundedSizingField<uniform_sizing>);

} // namespace pdd
