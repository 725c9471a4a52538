/// \file triangle_locator.hpp
/// Point location in a triangle soup through a Boost.Geometry R-tree of triangle boxes and
/// CGAL's exact orientation predicate (background meshes, regional faces).
#pragma once

#include <pdd/core/bbox.hpp>
#include <pdd/core/point.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
// the parts it uses, not all of Boost.Geometry (<boost/geometry.hpp>: 125K more lines to parse)
#include <boost/geometry/algorithms/disjoint.hpp>
#include <boost/geometry/geometries/box.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/index/rtree.hpp>
#include <boost/iterator/function_output_iterator.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <iterator>
#include <limits>
#include <utility>
#include <vector>

namespace pdd::detail {

/// A static set of triangles (vertex ids into a point array) with an R-tree over their boxes.
/// locate(p) returns the smallest id of a triangle holding p (closed triangles: boundary
/// points belong to every triangle that has them; the smallest id makes the answer
/// deterministic), or triangle_locator::not_found. Thread-safety: const queries may run
/// concurrently.
class triangle_locator {
public:
  using box_t = boost::geometry::model::box<boost::geometry::model::d2::point_xy<double>>;
  using value_t = std::pair<box_t, index_t>;

  static constexpr index_t not_found = std::numeric_limits<index_t>::max();

  triangle_locator() = default;
  /// Builds the R-tree (packing construction). Triangles may be in either orientation.
  /// Complexity O(T log T).
  triangle_locator(std::vector<point> vertices, std::vector<std::array<index_t, 3>> triangles)
      : vertices_(std::move(vertices)), triangles_(std::move(triangles)) {
    std::vector<value_t> boxes;
    boxes.reserve(triangles_.size());
    for (index_t t = 0; t < triangles_.size(); ++t)
      boxes.emplace_back(box_of(t), t);
    tree_ = rtree_t(boxes.begin(), boxes.end());
  }

  /// The triangle holding p (smallest id), or not_found. Complexity O(log T) expected.
  index_t locate(const point& p) const {
    using pt = boost::geometry::model::d2::point_xy<double>;
    index_t best = not_found;
    tree_.query(boost::geometry::index::intersects(pt(p.x, p.y)),
                boost::make_function_output_iterator([&](const value_t& v) {
                  if (v.second < best && contains(v.second, p)) best = v.second;
                }));
    return best;
  }

  /// Ids of the triangles whose box meets `b`, in increasing order.
  std::vector<index_t> overlapping(const pdd::bbox& b) const {
    using pt = boost::geometry::model::d2::point_xy<double>;
    std::vector<index_t> ids;
    if (b.empty()) return ids;
    const box_t q(pt(b.xmin, b.ymin), pt(b.xmax, b.ymax));
    tree_.query(
        boost::geometry::index::intersects(q),
        boost::make_function_output_iterator([&](const value_t& v) { ids.push_back(v.second); }));
    std::sort(ids.begin(), ids.end());
    return ids;
  }

  const std::vector<point>& vertices() const noexcept { return vertices_; }
  const std::vector<std::array<index_t, 3>>& triangles() const noexcept { return triangles_; }

private:
  using rtree_t = boost::geometry::index::rtree<value_t, boost::geometry::index::rstar<16>>;
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;

  box_t box_of(index_t t) const {
    using pt = boost::geometry::model::d2::point_xy<double>;
    const point& a = vertices_[triangles_[t][0]];
    const point& b = vertices_[triangles_[t][1]];
    const point& c = vertices_[triangles_[t][2]];
    return box_t(pt(std::min({a.x, b.x, c.x}), std::min({a.y, b.y, c.y})),
                 pt(std::max({a.x, b.x, c.x}), std::max({a.y, b.y, c.y})));
  }
  /// Exact: p is inside or on the closed triangle t.
  bool contains(index_t t, const point& p) const {
    const auto q = [&](index_t v) { return K::Point_2(vertices_[v].x, vertices_[v].y); };
    const K::Point_2 a = q(triangles_[t][0]), b = q(triangles_[t][1]), c = q(triangles_[t][2]);
    const K::Point_2 x(p.x, p.y);
    const auto o = CGAL::orientation(a, b, c);
    if (o == CGAL::COLLINEAR) return false;
    return CGAL::orientation(a, b, x) != -o && CGAL::orientation(b, c, x) != -o &&
           CGAL::orientation(c, a, x) != -o;
  }

  std::vector<point> vertices_;
  std::vector<std::array<index_t, 3>> triangles_;
  rtree_t tree_;
};

} // namespace pdd::detail
