/// \file background_mesh.hpp
/// pdd::background_mesh_sizing: a sizing field given on a background triangle mesh, either
/// one area per vertex (linear interpolation) or one area per triangle (piecewise constant,
/// Triangle's .area convention).
#pragma once

#include <pdd/concepts/sizing_field.hpp>
#include <pdd/errors.hpp>
#include <pdd/sizing/detail/triangle_locator.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace pdd {

/// Models BoundedSizingField from a background mesh (Gmsh's background mesh, Triangle's
/// -r with an .area file, JIGSAW's hfun on a mesh).
///  - per_vertex: values[v] is the area bound at vertex v (> 0); inside a triangle F is the
///    linear interpolation of its three vertex values.
///  - per_triangle: values[t] is the area bound of triangle t (Triangle's .area: a value <= 0
///    means no bound there); F is constant on each triangle; on an edge or vertex shared by
///    several triangles the smallest triangle id decides.
/// The containing triangle is found through an R-tree (O(log T) expected), never by a scan.
/// Outside every background triangle F is infinity (no bound).
/// range(box) is taken from the nodes (per_vertex) or triangle values (per_triangle) of the
/// triangles whose bounding box meets the box: lo is a true lower bound (F over a triangle
/// lies between its vertex values); hi bounds F over the part of the box the background mesh
/// covers. Thread-safety: const and shared; copies share the mesh.
class background_mesh_sizing {
public:
  /// How `values` define F: per_vertex (one area bound per vertex, linear over each triangle)
  /// or per_triangle (one per triangle, constant on it); see the class comment.
  enum class interpolation { per_vertex, per_triangle };

  /// \throws pdd::sizing_error naming the vertex or triangle: a vertex id out of range, a
  /// degenerate triangle, a per-vertex value <= 0 or not finite, a NaN, or a value count that
  /// does not match. Complexity O(T log T).
  background_mesh_sizing(std::vector<point> vertices, std::vector<std::array<index_t, 3>> triangles,
                         std::vector<double> values, interpolation mode)
      : data_(std::make_shared<data>()) {
    check(vertices, triangles, values, mode);
    if (mode == interpolation::per_triangle)
      for (double& v : values)
        if (v <= 0.0) v = std::numeric_limits<double>::infinity();
    data_->mode = mode;
    data_->values = std::move(values);
    data_->locator = detail::triangle_locator(std::move(vertices), std::move(triangles));
  }

  /// F(p): interpolated in the background triangle that holds p (see the class comment);
  /// infinity (no bound) outside every background triangle.
  double area_at(const point& p) const {
    const detail::triangle_locator& loc = data_->locator;
    const index_t t = loc.locate(p);
    if (t == detail::triangle_locator::not_found) return std::numeric_limits<double>::infinity();
    if (data_->mode == interpolation::per_triangle) return data_->values[t];
    const auto& tri = loc.triangles()[t];
    const point &a = loc.vertices()[tri[0]], &b = loc.vertices()[tri[1]],
                &c = loc.vertices()[tri[2]];
    const double det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    const double l1 = ((p.x - a.x) * (c.y - a.y) - (c.x - a.x) * (p.y - a.y)) / det;
    const double l2 = ((b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y)) / det;
    const double va = data_->values[tri[0]], vb = data_->values[tri[1]], vc = data_->values[tri[2]];
    const double v = va + l1 * (vb - va) + l2 * (vc - va);
    // rounding can leave v a hair outside the vertex values: clamp (F is convex-combined)
    return std::clamp(v, std::min({va, vb, vc}), std::max({va, vb, vc}));
  }

  /// Bounds of F over the closed box b from the values of the background triangles whose
  /// bounding box meets b; {infinity, infinity} when none does (see the class comment).
  sizing_bounds range(const bbox& b) const {
    constexpr double inf = std::numeric_limits<double>::infinity();
    sizing_bounds r{inf, 0.0};
    for (const index_t t : data_->locator.overlapping(b)) {
      if (data_->mode == interpolation::per_triangle) {
        r.lo = std::min(r.lo, data_->values[t]);
        r.hi = std::max(r.hi, data_->values[t]);
        continue;
      }
      for (const index_t v : data_->locator.triangles()[t]) {
        r.lo = std::min(r.lo, data_->values[v]);
        r.hi = std::max(r.hi, data_->values[v]);
      }
    }
    if (r.hi == 0.0) r.hi = inf;
    return r;
  }

  /// "background_mesh": the field's name in reports (any_sizing::kind, min_sizing::kind).
  static constexpr const char* kind() noexcept { return "background_mesh"; }
  /// How the values are interpolated, as given to the constructor.
  interpolation mode() const noexcept { return data_->mode; }
  /// The number of background triangles.
  std::size_t num_triangles() const noexcept { return data_->locator.triangles().size(); }

private:
  struct data {
    interpolation mode = interpolation::per_vertex;
    std::vector<double> values;
    detail::triangle_locator locator;
  };

  static void check(const std::vector<point>& vs, const std::vector<std::array<index_t, 3>>& ts,
                    const std::vector<double>& values, interpolation mode) {
    const bool per_vertex = mode == interpolation::per_vertex;
    const std::size_t want = per_vertex ? vs.size() : ts.size();
    if (values.size() != want)
      throw sizing_error("background mesh: " + std::to_string(values.size()) + " values for " +
                         std::to_string(want) + (per_vertex ? " vertices" : " triangles"));
    for (std::size_t i = 0; i < values.size(); ++i)
      if (std::isnan(values[i]) || (per_vertex && !(values[i] > 0.0 && std::isfinite(values[i]))))
        throw sizing_error("background mesh: the area of " +
                           std::string(per_vertex ? "vertex " : "triangle ") + std::to_string(i) +
                           " is " + std::to_string(values[i]) +
                           (per_vertex ? "; it must be finite and > 0" : ""));
    for (std::size_t t = 0; t < ts.size(); ++t) {
      for (const index_t v : ts[t])
        if (v >= vs.size())
          throw sizing_error("background mesh: triangle " + std::to_string(t) +
                             " refers to vertex " + std::to_string(v) + " of " +
                             std::to_string(vs.size()));
      const point &a = vs[ts[t][0]], &b = vs[ts[t][1]], &c = vs[ts[t][2]];
      if (CGAL::orientation(CGAL::Epick::Point_2(a.x, a.y), CGAL::Epick::Point_2(b.x, b.y),
                            CGAL::Epick::Point_2(c.x, c.y)) == CGAL::COLLINEAR)
        throw sizing_error("background mesh: triangle " + std::to_string(t) + " is degenerate");
    }
  }

  std::shared_ptr<data> data_;
};
static_assert(BoundedSizingField<background_mesh_sizing>);

} // namespace pdd
