/// \file loops.hpp
/// pdd::find_loops and pdd::domain_area: the closed loops of a PSLG, their orientation and
/// nesting, and the area of the meshed domain (faces enclosed by an odd number of loops,
/// Triangle's convention for closed loops with hole points).
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/core/triangulation_levels.hpp>
#include <pdd/errors.hpp>
#include <pdd/geometry/detail/loop_nesting.hpp>
#include <pdd/geometry/loop_structure.hpp>

#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace pdd {

/// Finds the closed loops of a PSLG, their orientation and their nesting.
///
/// Nesting is computed by a flood fill of the PSLG's constrained Delaunay triangulation
/// (CGAL, exact predicates) from the unbounded face: crossing a segment of loop L enters the
/// inside of L one level deeper. depth is the level outside the loop, parent the loop whose
/// inside (minus its children) is there.
/// \pre Segments do not intersect except at shared endpoints (see validate()).
/// \throws geometry_error if a vertex lies on 0 segments ("isolated vertices are not
///   supported yet") or on other than 2 ("dangling segments and internal constraint segments
///   are not supported yet", naming vertices and segments), on duplicate vertices or
///   segments, out-of-range or zero-length segments, and on intersecting segments.
/// Complexity O(n log n) expected (triangulation); thread-safe (no shared state).
inline loop_structure find_loops(const pslg& g) {
  detail::loops_with_triangulation lt;
  detail::find_loops_into(g, lt);
  return std::move(lt.structure);
}

/// Area of a loop structure's domain: loops at even depth add their area, loops at odd
/// depth (hole boundaries) subtract theirs.
inline double domain_area(const loop_structure& ls) {
  double area = 0.0;
  for (const polygon_loop& l : ls.loops)
    area += (l.bounds_domain_inside ? 1.0 : -1.0) * std::abs(l.signed_area);
  return area;
}

/// Area of the meshed domain: the regions enclosed by an odd number of loops.
/// \pre As find_loops(). \throws geometry_error as find_loops().
/// Complexity O(n log n) expected; thread-safe.
inline double domain_area(const pslg& g) {
  return domain_area(find_loops(g));
}

} // namespace pdd
