/// \file lfs.hpp
/// pdd::lfs_min: the minimum local feature size of a PSLG domain (dissertation Definition 1,
/// restricted to the domain as in Definition 7).
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/core/triangulation_levels.hpp>
#include <pdd/geometry/detail/lfs.hpp>
#include <pdd/geometry/loops.hpp>

#include <algorithm>

namespace pdd {

namespace detail {
/// lfs_min of a domain of closed loops by odd nesting with constraints inside it (a
/// subdomain of a general PSLG: dangling segments, isolated vertices, see
/// pdd::inner_constraint): the faces' nesting levels are flooded from the infinite face
/// (pdd::flood_levels; a face on both sides of a dangling segment is reached around it, so
/// its level is that of the face), then as lfs_min.
/// \throws geometry_error as build_cdt (duplicate vertices, intersecting segments).
inline double lfs_min_with_inner_constraints(const pslg& g) {
  loop_triangulation t;
  build_cdt(g, t);
  if (t.cdt.dimension() < 2)
    throw geometry_error("all vertices are collinear, so the segments overlap; pdd::validate "
                         "names them");
  flood_levels(t.cdt, [](pslg_cdt::Face_handle f) -> int& { return f->info().level; });
  return lfs_min(g, t);
}
} // namespace detail

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
/// Returns +infinity for a PSLG without segments. A PSLG whose vertices do not all lie on two
/// segments (closed loops with inner constraints: dangling segments, isolated vertices, as a
/// subdomain of a general PSLG) is read by odd nesting of its faces' flood levels
/// (detail::lfs_min_with_inner_constraints): its domain is that of its closed loops.
/// \pre The PSLG is valid (validate()): non-intersecting segments.
/// \throws geometry_error as find_loops().
/// Complexity O(n log n) expected; thread-safe.
inline double lfs_min(const pslg& g) {
  const detail::segment_incidence inc = detail::incident_segments(g);
  if (std::any_of(inc.degree.begin(), inc.degree.end(), [](index_t d) { return d != 2; }))
    return detail::lfs_min_with_inner_constraints(g);
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
