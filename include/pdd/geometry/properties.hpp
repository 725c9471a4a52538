/// \file properties.hpp
/// Geometric properties of a PSLG domain: bounding box, area, loop counts, smallest angle on
/// the domain side, minimum local feature size; pdd::analyze computes them all at once.
#pragma once

#include <pdd/core/bbox.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/geometry/detail/face_angles.hpp>
#include <pdd/geometry/detail/lfs.hpp>
#include <pdd/geometry/detail/properties.hpp>
#include <pdd/geometry/lfs.hpp>
#include <pdd/geometry/loops.hpp>
#include <pdd/geometry/validate.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>

namespace pdd {

/// The properties of a valid PSLG's domain that the pipeline's first step needs.
struct pslg_properties {
  double area = 0.0;                   ///< domain_area()
  bbox box;                            ///< bounding_box()
  std::size_t num_loops = 0;           ///< all loops
  std::size_t num_outer_loops = 0;     ///< loops with the domain inside (even depth)
  std::size_t num_holes = 0;           ///< loops with a hole inside (odd depth)
  double min_angle_deg = 360.0;        ///< smallest angle at a vertex on the domain side
  index_t min_angle_vertex = no_index; ///< the vertex where it occurs (smallest id on ties)
  double lfs_min = std::numeric_limits<double>::infinity(); ///< Definition 7
  /// The domain is one of closed loops (pdd::has_closed_loops). When false (internal or
  /// dangling segments, isolated vertices, touching loops, internal boundaries), the loop
  /// counts are 0, min_angle_deg is the smallest angle between consecutive segments at a
  /// vertex on the domain side (detail::min_face_angle_deg) and lfs_min is NaN (not computed:
  /// Definition 7 is pdd's for closed loops).
  bool closed_loops = true;
};

/// Bounding box of the vertices (an empty box, xmin = +inf, for no vertices).
/// Complexity O(V); thread-safe.
inline bbox bounding_box(const pslg& g) {
  bbox b;
  for (const point& p : g.vertices) {
    b.xmin = std::min(b.xmin, p.x);
    b.ymin = std::min(b.ymin, p.y);
    b.xmax = std::max(b.xmax, p.x);
    b.ymax = std::max(b.ymax, p.y);
  }
  return b;
}

/// Smallest angle between the two segments at a vertex, measured on the domain side (the
/// interior angle at vertices of loops with the domain inside, 360 minus the interior angle
/// of the hole polygon at hole vertices), over all loop vertices; 360 without loops.
/// \param vertex if not null, receives the vertex of the smallest angle (no_index if none).
/// \pre As find_loops(). \throws geometry_error as find_loops().
/// Complexity O(n log n) expected (the loops' nesting); thread-safe.
inline double min_domain_angle_deg(const pslg& g, index_t* vertex = nullptr) {
  return detail::min_domain_angle_deg(g, find_loops(g), vertex);
}

/// Validates a PSLG (validate()) and computes its properties, building the constrained
/// triangulation once for loops, nesting and lfs_min (see pslg_properties::closed_loops for a
/// domain that is not one of closed loops: its area is that of Triangle's faces).
/// \throws geometry_error as validate() with default options.
/// Complexity O(n log^2 n) (validation) plus O(n log n) expected; thread-safe.
inline pslg_properties analyze(const pslg& g) {
  detail::pslg_faces pf;
  detail::validate_into(g, validate_options{}, &pf);
  pslg_properties p;
  p.box = bounding_box(g);
  if (!pf.closed_loops) {
    p.closed_loops = false;
    p.area = detail::faces_area(pf);
    p.min_angle_deg = detail::min_face_angle_deg(g, pf, &p.min_angle_vertex);
    p.lfs_min = std::numeric_limits<double>::quiet_NaN();
    return p;
  }
  const detail::loops_with_triangulation& lt = pf.lt;
  p.area = domain_area(lt.structure);
  p.num_loops = lt.structure.loops.size();
  for (const polygon_loop& l : lt.structure.loops)
    ++(l.bounds_domain_inside ? p.num_outer_loops : p.num_holes);
  p.min_angle_deg = detail::min_domain_angle_deg(g, lt.structure, &p.min_angle_vertex);
  p.lfs_min = detail::lfs_min(g, lt.triangulation);
  return p;
}

} // namespace pdd
