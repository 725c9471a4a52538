/// \file point.hpp
/// The plain coordinate type used in every pdd value type.
#pragma once

#include <pdd/core/index.hpp>

#include <compare>
#include <cstdio>
#include <string>

namespace pdd {

/// A point in the plane. Ordered lexicographically (x, then y); equality is exact.
struct point {
  /// Abscissa, in the input's units.
  double x = 0.0;
  /// Ordinate, in the input's units.
  double y = 0.0;
  /// Lexicographic order (x first, then y) and exact equality, as std::tuple's.
  friend constexpr auto operator<=>(const point&, const point&) = default;
};

/// "(x, y)" with 17 significant digits (reads back to the same doubles): how pdd's messages
/// name a location.
inline std::string to_string(const point& p) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g)", p.x, p.y);
  return buf;
}

} // namespace pdd
