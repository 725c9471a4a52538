/// \file box_pairs.hpp
/// pdd::for_each_box_pair: every pair of intersecting axis-aligned boxes, from a packed
/// R-tree (Boost.Geometry's index, Boost Software License); pdd's candidate pairs for the exact
/// segment intersection tests (CGAL's Box_intersection_d is GPL: see PDD_PERMISSIVE).
#pragma once

#include <pdd/core/bbox.hpp>
#include <pdd/core/point.hpp>

#ifndef BOOST_ALLOW_DEPRECATED_HEADERS
#define BOOST_ALLOW_DEPRECATED_HEADERS // a deprecated Boost header rtree.hpp includes
#define PDD_BOX_PAIRS_UNDEF_DEPRECATED
#endif
#include <boost/geometry/geometries/box.hpp>
#include <boost/geometry/geometries/point.hpp>
#include <boost/geometry/index/rtree.hpp>
#ifdef PDD_BOX_PAIRS_UNDEF_DEPRECATED
#undef BOOST_ALLOW_DEPRECATED_HEADERS
#undef PDD_BOX_PAIRS_UNDEF_DEPRECATED
#endif
#include <boost/iterator/function_output_iterator.hpp>

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace pdd {

/// The bounding box of the segment [a, b].
inline bbox segment_box(const point& a, const point& b) noexcept {
  return {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
}

/// Calls pair(i, j), i < j, once for every two of `boxes` that intersect (closed: boxes that
/// touch count). The order of the calls is deterministic (a function of the boxes alone).
/// Complexity O(n log n + k) expected for n boxes and k pairs. Thread-safe (no shared state).
template <class Pair>
void for_each_box_pair(const std::vector<bbox>& boxes, Pair&& pair) {
  namespace bg = boost::geometry;
  namespace bgi = boost::geometry::index;
  using bpoint = bg::model::point<double, 2, bg::cs::cartesian>;
  using bbox_2 = bg::model::box<bpoint>;
  using value = std::pair<bbox_2, std::size_t>;
  std::vector<value> values;
  values.reserve(boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i)
    values.emplace_back(
        bbox_2(bpoint(boxes[i].xmin, boxes[i].ymin), bpoint(boxes[i].xmax, boxes[i].ymax)), i);
  const bgi::rtree<value, bgi::rstar<16>> tree(values.begin(), values.end());
  for (std::size_t i = 0; i < values.size(); ++i)
    tree.query(bgi::intersects(values[i].first),
               boost::make_function_output_iterator([&](const value& v) {
                 if (v.second > i) pair(i, v.second);
               }));
}

} // namespace pdd
