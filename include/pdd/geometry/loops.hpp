/// \file loops.hpp
/// pdd::find_loops and pdd::domain_area: the closed loops of a PSLG, their orientation and
/// nesting, and the area of the meshed domain (faces enclosed by an odd number of loops,
/// Triangle's convention for closed loops with hole points).
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/core/triangulation_levels.hpp>
#include <pdd/errors.hpp>
#include <pdd/geometry/detail/loop_nesting.hpp>
#include <pdd/geometry/detail/pslg_faces.hpp>
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

/// Area of the meshed domain by g.rule: odd_nesting, the regions enclosed by an odd number of
/// loops (from the loops' shoelace areas); triangle, the faces of Triangle's rule (the sum of
/// the areas of their constrained Delaunay triangles; the loops' areas when the domain is one
/// of closed loops, so that both rules give the same number there).
/// \pre odd_nesting: as find_loops(); triangle: g passed pdd::validate.
/// \throws geometry_error as find_loops() or pdd::validate.
/// Complexity O(n log n) expected; thread-safe.
inline double domain_area(const pslg& g) {
  if (g.rule == domain_rule::odd_nesting) return domain_area(find_loops(g));
  detail::pslg_faces pf;
  detail::find_faces_into(g, pf);
  return pf.closed_loops ? domain_area(pf.lt.structure) : detail::faces_area(pf);
}

} // namespace pdd
