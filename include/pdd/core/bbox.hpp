/// \file bbox.hpp
/// pdd::bbox: an axis-aligned bounding box.
#pragma once

#include <limits>

namespace pdd {

/// An axis-aligned bounding box (empty: xmin = +inf).
struct bbox {
  /// Smallest x of the box; +infinity in an empty box (the default).
  double xmin = std::numeric_limits<double>::infinity();
  /// Smallest y of the box; +infinity in an empty box (the default).
  double ymin = std::numeric_limits<double>::infinity();
  /// Largest x of the box; -infinity in an empty box (the default).
  double xmax = -std::numeric_limits<double>::infinity();
  /// Largest y of the box; -infinity in an empty box (the default).
  double ymax = -std::numeric_limits<double>::infinity();
  /// Extent in x, xmax - xmin (0 for a box of one point; -infinity for an empty box).
  double width() const noexcept { return xmax - xmin; }
  /// Extent in y, ymax - ymin (0 for a box of one point; -infinity for an empty box).
  double height() const noexcept { return ymax - ymin; }
  /// True when the box holds no point (xmin > xmax or ymin > ymax).
  bool empty() const noexcept { return !(xmin <= xmax && ymin <= ymax); }
};

} // namespace pdd
