/// \file uniform.hpp
/// pdd::uniform_sizing: the same area bound everywhere.
#pragma once

#include <pdd/concepts/sizing_field.hpp>

#include <limits>

namespace pdd {

/// Models SizingField with one area bound everywhere (infinity: no bound).
struct uniform_sizing {
  double area = std::numeric_limits<double>::infinity();
  double area_at(const point&) const noexcept { return area; }
};
static_assert(SizingField<uniform_sizing>);

} // namespace pdd
