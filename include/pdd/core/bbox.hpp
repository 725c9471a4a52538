/// \file bbox.hpp
/// pdd::bbox: an axis-aligned bounding box.
#pragma once

#include <limits>

namespace pdd {

/// An axis-aligned bounding box (empty: xmin = +inf).
struct bbox {
  double xmin = std::numeric_limits<double>::infinity();
  double ymin = std::numeric_limits<double>::infinity();
  double xmax = -std::numeric_limits<double>::infinity();
  double ymax = -std::numeric_limits<double>::infinity();
  double width() const noexcept { return xmax - xmin; }
  double height() const noexcept { return ymax - ymin; }
  /// True when the box holds no point (xmin > xmax or ymin > ymax).
  bool empty() const noexcept { return !(xmin <= xmax && ymin <= ymax); }
};

} // namespace pdd
