/// \file piecewise_scaled.hpp
/// pdd::piecewise_scaled_sizing: a sizing field scaled by one factor per piece of a partition
/// of the domain (the F of dissertation Algorithm 8.3, step 12: F|D_i = f|D_i g_i / m_f(D_i)).
#pragma once

#include <pdd/concepts/sizing_field.hpp>
#include <pdd/core/bbox.hpp>
#include <pdd/core/index.hpp>
#include <pdd/core/point.hpp>
#include <pdd/errors.hpp>
#include <pdd/sizing/any_sizing.hpp>
#include <pdd/sizing/background_mesh.hpp>
#include <pdd/sizing/sizing_region.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace pdd {

/// F(p) = min(max_area, f(p)) * scale[i] for p in piece i. The pieces are given as triangles
/// (a triangulation of each piece; piece_of[t] names the piece of triangle t) and located
/// through an R-tree (pdd::background_mesh_sizing's locator, per triangle); on an edge shared
/// by two pieces the smaller triangle id decides (triangle centroids, where the kernel and
/// pdd::verify evaluate F, lie inside one piece). Outside every triangle the smallest scale
/// applies (a lower bound everywhere).
/// range(box): lo = (lower bound of min(max_area, f) over the box) * (smallest scale of the
/// triangles meeting the box): a true lower bound when f's is; hi likewise an upper bound.
/// piece_bounds(i) are the exact m_F(D_i), M_F(D_i) given at construction.
/// Models BoundedSizingField. Thread-safety: const and shared; copies share the data.
class piecewise_scaled_sizing {
public:
  /// \throws pdd::sizing_error for a scale that is not in (0, infinity), a piece id out of
  /// range, mismatched sizes, or as pdd::background_mesh_sizing for bad triangles.
  piecewise_scaled_sizing(any_sizing base, double max_area, std::vector<point> vertices,
                          std::vector<std::array<index_t, 3>> triangles,
                          const std::vector<index_t>& piece_of, std::vector<double> scale,
                          std::vector<sizing_bounds> piece_bounds)
      : data_(std::make_shared<data>(
            data{std::move(base), max_area,
                 build(std::move(vertices), std::move(triangles), piece_of, scale), scale,
                 std::move(piece_bounds), 0.0})) {
    if (data_->bounds.size() != scale.size())
      throw sizing_error("piecewise_scaled_sizing: " + std::to_string(data_->bounds.size()) +
                         " piece bounds for " + std::to_string(scale.size()) + " pieces");
    data_->min_scale = scale.empty() ? 1.0 : *std::min_element(scale.begin(), scale.end());
  }

  /// F(p) = min(max_area, f(p)) * the scale of the piece that holds p (the smallest scale
  /// outside every triangle).
  double area_at(const point& p) const {
    double s = data_->located.area_at(p);
    if (!std::isfinite(s)) s = data_->min_scale;
    return base_at(p) * s;
  }

  /// Bounds of F over the closed box b (see the class comment), the base field's bounds from
  /// pdd::sizing_range with default options.
  sizing_bounds range(const bbox& b) const { return range(b, sizing_range_options{}); }
  /// range with pdd::sizing_range's options for the base field.
  sizing_bounds range(const bbox& b, const sizing_range_options& o) const {
    return scaled(data_->base.range(b, o), b);
  }
  /// Bounds of F over the closed region r: the base field's bounds over the region (evaluated
  /// only there), the scales of the triangles meeting the region's box.
  sizing_bounds range(const sizing_region& r, const sizing_range_options& o) const {
    return scaled(data_->base.range(r, o), r.box());
  }

  /// "geometric" (the field of the geometric graded method, Algorithm 8.3): its name in
  /// reports (any_sizing::kind, min_sizing::kind).
  static constexpr const char* kind() noexcept { return "geometric"; }
  /// The number of pieces D_i (the size of `scale` given at construction).
  std::size_t pieces() const noexcept { return data_->scale.size(); }
  /// The factor of piece i (g_i / m_f(D_i) in Algorithm 8.3).
  double scale(std::size_t i) const { return data_->scale.at(i); }
  /// m_F(D_i), M_F(D_i) as given at construction.
  const sizing_bounds& piece_bounds(std::size_t i) const { return data_->bounds.at(i); }
  /// min(max_area, f(p)): the field before scaling.
  double base_at(const point& p) const { return std::min(data_->max_area, data_->base.area_at(p)); }

private:
  struct data {
    any_sizing base;
    double max_area;
    background_mesh_sizing located; ///< per triangle: the scale of its piece
    std::vector<double> scale;
    std::vector<sizing_bounds> bounds;
    double min_scale;
  };

  /// The bounds of min(max_area, f) given as `base`, times the scales over box b.
  sizing_bounds scaled(sizing_bounds base, const bbox& b) const {
    base.lo = std::min(base.lo, data_->max_area);
    base.hi = std::min(base.hi, data_->max_area);
    sizing_bounds s = data_->located.range(b);
    if (!std::isfinite(s.lo)) s = {data_->min_scale, data_->min_scale};
    return {base.lo * s.lo, base.hi * std::max(s.hi, s.lo)};
  }

  static background_mesh_sizing build(std::vector<point> vertices,
                                      std::vector<std::array<index_t, 3>> triangles,
                                      const std::vector<index_t>& piece_of,
                                      const std::vector<double>& scale) {
    if (piece_of.size() != triangles.size())
      throw sizing_error("piecewise_scaled_sizing: " + std::to_string(piece_of.size()) +
                         " piece ids for " + std::to_string(triangles.size()) + " triangles");
    std::vector<double> values(triangles.size());
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      if (piece_of[t] >= scale.size())
        throw sizing_error("piecewise_scaled_sizing: triangle " + std::to_string(t) +
                           " names piece " + std::to_string(piece_of[t]) + " of " +
                           std::to_string(scale.size()));
      const double s = scale[piece_of[t]];
      if (!(s > 0.0) || !std::isfinite(s))
        throw sizing_error("piecewise_scaled_sizing: the scale of piece " +
                           std::to_string(piece_of[t]) + " is not in (0, infinity)");
      values[t] = s;
    }
    return background_mesh_sizing(std::move(vertices), std::move(triangles), std::move(values),
                                  background_mesh_sizing::interpolation::per_triangle);
  }

  std::shared_ptr<data> data_;
};
static_assert(BoundedSizingField<piecewise_scaled_sizing>);

} // namespace pdd
