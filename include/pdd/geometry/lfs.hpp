/// \file lfs.hpp
/// pdd::lfs_min: the minimum local feature size of a PSLG domain (dissertation Definition 1,
/// restricted to the domain as in Definition 7).
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/geometry/detail/lfs.hpp>
#include <pdd/geometry/loops.hpp>

namespace pdd {

/// Minimum local feature size of the domain (Definition 7, after Definition 1): the minimum
/// distance between two non-incident entities (vertex-vertex, vertex-segment,
/// segment-segment) whose connecting straight line lies in the closed domain (the faces
/// enclosed by an odd number of loops, with their boundary). Distances across holes or
/// outside the domain do not count.
///
/// Computed on the PSLG's constrained Delaunay triangulation (CGAL, exact predicates): the
/// shortest triangulation edge in the closed domain, and the perpendicular distance from
/// each vertex to each segment reached by a pruned search through the domain's triangles
/// whose perpendicular stays inside the domain (see detail::lfs_min for the argument).
/// Returns +infinity for a PSLG without segments.
/// \pre The PSLG is valid (validate()): closed, non-intersecting loops.
/// \throws geometry_error as find_loops().
/// Complexity O(n log n) expected; thread-safe.
inline double lfs_min(const pslg& g) {
  detail::loops_with_triangulation lt;
  detail::find_loops_into(g, lt);
  return detail::lfs_min(g, lt.triangulation);
}

/// lfs_min(g) for a pslg whose loops detail::find_loops_into has already traced into lt (its
/// triangulation is reused). \pre lt = find_loops_into(g). Complexity and errors as lfs_min(g).
inline double lfs_min(const pslg& g, const detail::loops_with_triangulation& lt) {
  return detail::lfs_min(g, lt.triangulation);
}

} // namespace pdd
