/// \file point_set.hpp
/// Triangle without -p: the input is a vertex set. Equal vertices found exactly (Triangle keeps
/// the first and ignores the others, with a warning), the Delaunay triangulation of the distinct
/// ones (CGAL's Delaunay_triangulation_2, exact predicates) and their convex hull as a loop
/// through every vertex on its boundary (collinear ones too, as Triangle's hull segments).
#pragma once

#include <pdd/core/kernel.hpp>
#include <pdd/core/point.hpp>
#include <pdd/errors.hpp>
#include <pdd/triangulation/constrained_delaunay_2.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace pdd::triangle::detail {

/// The distinct vertices of a vertex set.
struct distinct_vertices {
  /// first[i]: the first input vertex with the coordinates of vertex i (i when it is the first).
  std::vector<index_t> first;
  std::vector<index_t> kept; ///< the input ids with first[i] == i, increasing
};

/// Finds equal vertices (exact comparison of the coordinates: no tolerance).
/// Complexity O(n log n).
inline distinct_vertices find_distinct(const std::vector<point>& v) {
  std::vector<index_t> order(v.size());
  std::iota(order.begin(), order.end(), index_t{0});
  std::sort(order.begin(), order.end(),
            [&v](index_t a, index_t b) { return v[a] < v[b] || (v[a] == v[b] && a < b); });
  distinct_vertices d;
  d.first.resize(v.size());
  for (std::size_t k = 0; k < order.size(); ++k)
    d.first[order[k]] = k > 0 && v[order[k]] == v[order[k - 1]] ? d.first[order[k - 1]] : order[k];
  for (std::size_t i = 0; i < v.size(); ++i)
    if (d.first[i] == i) d.kept.push_back(static_cast<index_t>(i));
  return d;
}

/// The Delaunay triangulation of a vertex set, in input ids.
struct point_set_delaunay {
  /// Counter-clockwise, each starting at its smallest id, sorted (independent of the
  /// insertion order and of CGAL's storage).
  std::vector<std::array<index_t, 3>> triangles;
  /// The convex hull counter-clockwise from its smallest id: every vertex on its boundary.
  std::vector<index_t> hull;
};

/// The Delaunay triangulation of a vertex set: a constrained one without constraints (vertex
/// info: the input id).
using delaunay_2 = constrained_delaunay_2<index_t>;

/// The hull of a 2-dimensional triangulation: the edges of its infinite faces, the finite
/// side on the left, chained from the smallest id.
inline std::vector<index_t> hull_loop(const delaunay_2& dt, std::size_t id_count) {
  std::vector<index_t> next(id_count, no_index);
  index_t start = no_index;
  for (const auto f : dt.all_face_handles()) {
    if (!dt.is_infinite(f)) continue;
    const int i = f->index(dt.infinite_vertex());
    const index_t a = f->vertex(delaunay_2::cw(i))->info();
    next[a] = f->vertex(delaunay_2::ccw(i))->info();
    start = std::min(start, a);
  }
  std::vector<index_t> hull{start};
  for (index_t v = next[start]; v != start; v = next[v])
    hull.push_back(v);
  return hull;
}

/// The Delaunay triangulation of the vertices `ids` of v (distinct points).
/// \throws pdd::geometry_error for fewer than three vertices or when all are collinear (no
///   triangle: Triangle would output an empty mesh).
/// Complexity O(n log n) expected. Thread-safety: reentrant.
inline point_set_delaunay delaunay_of(const std::vector<point>& v,
                                      const std::vector<index_t>& ids) {
  if (ids.size() < 3)
    throw geometry_error("the input must have at least three distinct vertices (it has " +
                         std::to_string(ids.size()) + ")");
  std::vector<std::pair<epick::Point_2, index_t>> pts;
  pts.reserve(ids.size());
  for (const index_t i : ids)
    pts.emplace_back(epick::Point_2(v[i].x, v[i].y), i);
  delaunay_2 dt;
  dt.insert(pts.begin(), pts.end());
  if (dt.dimension() < 2)
    throw geometry_error("all " + std::to_string(ids.size()) +
                         " distinct vertices are collinear: their Delaunay triangulation has no "
                         "triangle");
  point_set_delaunay out;
  out.triangles.reserve(static_cast<std::size_t>(dt.number_of_faces()));
  for (const auto f : dt.finite_face_handles()) {
    std::array<index_t, 3> t{f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    out.triangles.push_back(t);
  }
  std::sort(out.triangles.begin(), out.triangles.end());
  out.hull = hull_loop(dt, v.size());
  return out;
}

} // namespace pdd::triangle::detail
