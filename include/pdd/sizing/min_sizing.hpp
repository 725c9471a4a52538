/// \file min_sizing.hpp
/// pdd::min_sizing: the pointwise minimum of several sizing fields (e.g. a user field and a
/// uniform --max-area).
#pragma once

#include <pdd/concepts/sizing_field.hpp>
#include <pdd/sizing/sizing_range.hpp>
#include <pdd/sizing/sizing_region.hpp>

#include <algorithm>
#include <limits>
#include <string>
#include <tuple>

namespace pdd {

/// Models BoundedSizingField as F(p) = min_i F_i(p). Its range is {min_i lo_i, min_i hi_i}
/// with each field's bounds from pdd::sizing_range (a true lower bound when every lo_i is:
/// F >= min_i F_i >= min_i lo_i; and F <= F_i <= hi_i for every i).
/// \tparam Fs SizingFields. Thread-safe when they are.
template <SizingField... Fs>
requires(sizeof...(Fs) > 0) struct min_sizing {
  /// The fields F_i whose minimum this is, in the order given.
  std::tuple<Fs...> fields;

  /// The minimum of the fields `fs` (at least one).
  explicit min_sizing(Fs... fs) : fields(std::move(fs)...) {}

  /// min_i F_i(p): the smallest area bound of the fields at p.
  double area_at(const point& p) const {
    return std::apply(
        [&](const auto&... f) { return std::min({static_cast<double>(f.area_at(p))...}); }, fields);
  }
  /// {min_i lo_i, min_i hi_i} over the closed box b, each field's bounds from pdd::sizing_range
  /// with default options.
  sizing_bounds range(const bbox& b) const { return range(b, sizing_range_options{}); }
  /// range with pdd::sizing_range's options for every field.
  sizing_bounds range(const bbox& b, const sizing_range_options& o) const {
    return combined_range(b, o);
  }
  /// {min_i lo_i, min_i hi_i} over the closed region r, each field's bounds from
  /// pdd::sizing_range over the region.
  sizing_bounds range(const sizing_region& r, const sizing_range_options& o) const {
    return combined_range(r, o);
  }
  /// "min(kind_1, kind_2, ...)".
  std::string kind() const {
    return std::apply(
        [](const auto&... f) {
          std::string s;
          ((s += (s.empty() ? "" : ", ") + std::string(kind_of(f))), ...);
          return "min(" + s + ")";
        },
        fields);
  }

private:
  /// {min_i lo_i, min_i hi_i} of pdd::sizing_range(F_i, where, o): `where` a box or a region.
  template <class Where>
  sizing_bounds combined_range(const Where& where, const sizing_range_options& o) const {
    return std::apply(
        [&](const auto&... f) {
          sizing_bounds r{std::numeric_limits<double>::infinity(),
                          std::numeric_limits<double>::infinity()};
          ((r = combine(r, sizing_range(f, where, o))), ...);
          return r;
        },
        fields);
  }
  static sizing_bounds combine(sizing_bounds a, sizing_bounds b) {
    return {std::min(a.lo, b.lo), std::min(a.hi, b.hi)};
  }
  template <class F>
  static std::string kind_of(const F& f) {
    if constexpr (requires { f.kind(); })
      return std::string(f.kind());
    else
      return "callable";
  }
};

} // namespace pdd
