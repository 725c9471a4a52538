/// \file point.hpp
/// The plain coordinate type used in every pdd value type.
#pragma once

#include <pdd/core/index.hpp>

#include <compare>

namespace pdd {

/// A point in the plane. Ordered lexicographically (x, then y); equality is exact.
struct point {
  double x = 0.0;
  double y = 0.0;
  friend constexpr auto operator<=>(const point&, const point&) = default;
};

} // namespace pdd
