/// \file any_sizing.hpp
/// pdd::any_sizing: a type-erased SizingField, so that non-template options
/// (pdd::generate_options) can hold any field.
#pragma once

#include <pdd/concepts/sizing_field.hpp>
#include <pdd/sizing/sizing_range.hpp>
#include <pdd/sizing/sizing_region.hpp>

#include <limits>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>

namespace pdd {

/// Holds any SizingField by value (shared, immutable) and models BoundedSizingField: area_at
/// and range forward to the held field (range through pdd::sizing_range, so an unbounded
/// field is bounded by the grid rule). An empty any_sizing (default) has no bound: area_at is
/// infinity everywhere. kind() names the field ("none" when empty; the field's own kind() or
/// "callable").
/// Thread-safety: as the held field; copies share it. Cost: one virtual call per area_at.
class any_sizing {
public:
  any_sizing() = default;
  // area_at is checked before SizingField's copy_constructible, so that wrappers holding an
  // any_sizing (std::tuple's storage) do not make the constraint depend on itself
  /// Holds a copy of `field` (any SizingField; implicit, so a field converts to any_sizing).
  template <class F>
  requires(!std::is_same_v<std::remove_cvref_t<F>, any_sizing> &&
           requires(const F& f, const point& p) { f.area_at(p); } && SizingField<F>)
      any_sizing(F field) // NOLINT(google-explicit-constructor): a field converts implicitly
      : impl_(std::make_shared<model<F>>(std::move(field))) {}

  /// True when a field is held.
  explicit operator bool() const noexcept { return impl_ != nullptr; }
  /// The held field's area_at(p); infinity (no bound) when empty.
  double area_at(const point& p) const {
    return impl_ ? impl_->area_at(p) : std::numeric_limits<double>::infinity();
  }
  /// Bounds of the held field over the closed box b (pdd::sizing_range with default options:
  /// the field's own range, else the grid rule); {infinity, infinity} when empty.
  sizing_bounds range(const bbox& b) const { return range(b, sizing_range_options{}); }
  /// range with pdd::sizing_range's options for the held field.
  sizing_bounds range(const bbox& b, const sizing_range_options& o) const {
    if (!impl_)
      return {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    return impl_->range(b, o);
  }
  /// Bounds of the held field over the closed region r (pdd::sizing_range over the region:
  /// evaluated only in the region); {infinity, infinity} when empty.
  sizing_bounds range(const sizing_region& r, const sizing_range_options& o) const {
    if (!impl_)
      return {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    return impl_->range(r, o);
  }
  /// The held field's name: its own kind(), "callable" when it has none, "none" when empty.
  std::string kind() const { return impl_ ? impl_->kind() : "none"; }

private:
  struct base {
    virtual ~base() = default;
    virtual double area_at(const point& p) const = 0;
    virtual sizing_bounds range(const bbox& b, const sizing_range_options& o) const = 0;
    virtual sizing_bounds range(const sizing_region& r, const sizing_range_options& o) const = 0;
    virtual std::string kind() const = 0;
  };
  template <class F>
  struct model final : base {
    explicit model(F f) : field(std::move(f)) {}
    double area_at(const point& p) const override { return static_cast<double>(field.area_at(p)); }
    sizing_bounds range(const bbox& b, const sizing_range_options& o) const override {
      return sizing_range(field, b, o);
    }
    sizing_bounds range(const sizing_region& r, const sizing_range_options& o) const override {
      return sizing_range(field, r, o);
    }
    std::string kind() const override {
      if constexpr (requires { field.kind(); })
        return std::string(field.kind());
      else
        return "callable";
    }
    F field;
  };
  std::shared_ptr<const base> impl_;
};
static_assert(BoundedSizingField<any_sizing>);

} // namespace pdd
