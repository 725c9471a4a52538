/// \file feature_driven_sizing.hpp
/// pdd::feature_driven_sizing: the field that drives the geometric loop's decompositions
/// towards tiny features (pdd::geometric_decompose).
#pragma once

#include <pdd/core/bbox.hpp>
#include <pdd/core/point.hpp>
#include <pdd/sizing/any_sizing.hpp>
#include <pdd/sizing/sizing_region.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <numbers>
#include <utility>
#include <vector>

namespace pdd {

/// The driving field of a refined round: min(max_area, f(x), min over tiny-feature vertices v
/// of 4 sqrt2 (gap(v)/2 + slope |x - v|)^2), the area bound (relation 8.12 with e = lfs) of a
/// feature size growing by `slope` per unit of distance from v. Why slope < 1 (lfs itself is
/// 1-Lipschitz): Algorithm 7.1 makes subdomains a fixed fraction of their distance from v, and
/// Algorithm 8.3 bounds F by lfs_min(D_i), which the subdomain's own size bounds; where the
/// driver reaches f the subdomains must already be several mesh edges wide, or F stays below
/// f there and the R2 propagation carries that far out. A smaller slope reaches f farther out.
/// range(box) is exact for the distance term (nearest and farthest point of the box from v)
/// and f's own range otherwise. It only shapes the decomposition; F's guarantees come from
/// Algorithm 8.3 with the exact lfs_min(D_i). Thread-safety: const and shared.
class feature_driven_sizing {
public:
  /// \pre slope >= 0, half_gap[i] >= 0.
  feature_driven_sizing(any_sizing base, double max_area, std::vector<point> at,
                        std::vector<double> half_gap, double slope)
      : data_(sorted_by_x(
            data{std::move(base), max_area, std::move(at), std::move(half_gap), slope})) {}
  /// min(max_area, f(p), bound(i, |p - v_i|) over i), measuring only the features that can
  /// beat the minimum so far: bound grows with e = gap/2 + slope * distance, so a feature
  /// counts only where e is below the current minimum's (`reach`, compared squared, with a
  /// relative margin of 1e-9 that only ever measures more), which also bounds |x - v_i.x|: the
  /// features are sorted by x and those of the slab are read. The result is the plain minimum
  /// over all features. This is the hot path of Algorithm 7.1 with hundreds of tiny features
  /// (on the Bahamas it was half of a whole pdd-mesh run).
  double area_at(const point& p) const {
    const data& d = *data_;
    double best = std::min(d.max_area, d.base.area_at(p));
    double reach = reach_of(best);
    if (!(d.min_half_gap < reach)) return best;
    const double half_width = (reach - d.min_half_gap) / d.slope; // +inf for slope 0
    const auto by_x = [](const point& a, double x) { return a.x < x; };
    const auto first = std::lower_bound(d.at.begin(), d.at.end(), p.x - half_width, by_x);
    for (auto it = first; it != d.at.end() && it->x <= p.x + half_width; ++it) {
      const auto i = static_cast<std::size_t>(it - d.at.begin());
      const double within = reach - d.half_gap[i];
      if (!(within > 0.0)) continue;
      const double dx = p.x - it->x;
      const double dy = p.y - it->y;
      const double squared = dx * dx + dy * dy;
      if (d.slope * d.slope * squared > within * within) continue;
      const double b = bound(i, std::sqrt(squared));
      if (b < best) {
        best = b;
        reach = reach_of(best);
      }
    }
    return best;
  }
  /// Bounds over the closed box b: min(max_area, f)'s range, and per feature the driver's
  /// bound at the nearest (lo) and farthest (hi) point of the box from it (see the class
  /// comment).
  sizing_bounds range(const bbox& b) const { return with_features(data_->base.range(b), b); }
  /// Bounds over the closed region r: f's over the region (evaluated only there), the
  /// features' over its box.
  sizing_bounds range(const sizing_region& r, const sizing_range_options& o) const {
    return with_features(data_->base.range(r, o), r.box());
  }
  /// "feature_driven": the field's name in reports (any_sizing::kind, min_sizing::kind).
  static constexpr const char* kind() noexcept { return "feature_driven"; }

private:
  /// f's bounds `r` capped by max_area and by each feature's bound over box b.
  sizing_bounds with_features(sizing_bounds r, const bbox& b) const {
    r = {std::min(r.lo, data_->max_area), std::min(r.hi, data_->max_area)};
    for (std::size_t i = 0; i < data_->at.size(); ++i) {
      const point q = data_->at[i];
      const double dx = std::max({b.xmin - q.x, 0.0, q.x - b.xmax});
      const double dy = std::max({b.ymin - q.y, 0.0, q.y - b.ymax});
      const double fx = std::max(std::abs(q.x - b.xmin), std::abs(q.x - b.xmax));
      const double fy = std::max(std::abs(q.y - b.ymin), std::abs(q.y - b.ymax));
      r.lo = std::min(r.lo, bound(i, std::hypot(dx, dy)));
      r.hi = std::min(r.hi, bound(i, std::hypot(fx, fy)));
    }
    return r;
  }

  /// The e = gap/2 + slope * distance at which bound reaches `area`, slightly enlarged.
  static double reach_of(double area) {
    return std::sqrt(area / (4.0 * std::numbers::sqrt2)) * (1.0 + 1e-9);
  }
  /// 4 sqrt2 e^2 with e = gap(v_i)/2 + slope * distance.
  double bound(std::size_t i, double distance) const {
    const double e = data_->half_gap[i] + data_->slope * distance;
    return 4.0 * std::numbers::sqrt2 * e * e;
  }
  struct data {
    any_sizing base;
    double max_area;
    std::vector<point> at;
    std::vector<double> half_gap;
    double slope;
    double min_half_gap = std::numeric_limits<double>::infinity();
  };
  /// Sorted by x (then y): area_at reads the slab of features near p's x.
  static std::shared_ptr<const data> sorted_by_x(data in) {
    std::vector<std::size_t> order(in.at.size());
    for (std::size_t i = 0; i < order.size(); ++i)
      order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return std::pair(in.at[a].x, in.at[a].y) < std::pair(in.at[b].x, in.at[b].y);
    });
    auto out = std::make_shared<data>(data{std::move(in.base),
                                           in.max_area,
                                           {},
                                           {},
                                           in.slope,
                                           std::numeric_limits<double>::infinity()});
    for (const std::size_t i : order) {
      out->at.push_back(in.at[i]);
      out->half_gap.push_back(in.half_gap[i]);
      out->min_half_gap = std::min(out->min_half_gap, in.half_gap[i]);
    }
    return out;
  }
  std::shared_ptr<const data> data_;
};

} // namespace pdd
