/// \file properties.hpp
/// Geometric properties of a PSLG domain: bounding box, area, loop counts, smallest angle on
/// the domain side, minimum local feature size; pdd::analyze computes them all at once.
#pragma once

#include <pdd/core/bbox.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/geometry/detail/lfs.hpp>
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

namespace detail {
/// Angle in degrees at v, turning counter-clockwise from direction v->to_ccw_from to
/// direction v->to; in (0, 360).
inline double ccw_angle_deg(const point& v, const point& from, const point& to) {
  const double ax = from.x - v.x, ay = from.y - v.y, bx = to.x - v.x, by = to.y - v.y;
  double a = std::atan2(ax * by - ay * bx, ax * bx + ay * by);
  if (a < 0) a += 2 * std::numbers::pi;
  return a * 180.0 / std::numbers::pi;
}

/// Smallest domain-side angle over all loop vertices; the vertex in *vertex.
inline double min_domain_angle_deg(const pslg& g, const loop_structure& ls, index_t* vertex) {
  double best = 360.0;
  index_t where = no_index;
  for (const polygon_loop& l : ls.loops) {
    const std::size_t n = l.vertices.size();
    for (std::size_t i = 0; i < n; ++i) {
      const point& prev = g.vertices[l.vertices[(i + n - 1) % n]];
      const point& v = g.vertices[l.vertices[i]];
      const point& next = g.vertices[l.vertices[(i + 1) % n]];
      // domain on the left of prev -> v -> next: the angle from v->next round to v->prev
      const double a =
          l.domain_on_left() ? ccw_angle_deg(v, next, prev) : ccw_angle_deg(v, prev, next);
      if (a < best || (a == best && l.vertices[i] < where)) {
        best = a;
        where = l.vertices[i];
      }
    }
  }
  if (vertex) *vertex = where;
  return best;
}
} // namespace detail

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
/// triangulation once for loops, nesting and lfs_min.
/// \throws geometry_error as validate() with default options.
/// Complexity O(n log^2 n) (validation) plus O(n log n) expected; thread-safe.
inline pslg_properties analyze(const pslg& g) {
  detail::loops_with_triangulation lt;
  detail::validate_into(g, validate_options{}, &lt);
  pslg_properties p;
  p.area = domain_area(lt.structure);
  p.box = bounding_box(g);
  p.num_loops = lt.structure.loops.size();
  for (const polygon_loop& l : lt.structure.loops)
    ++(l.bounds_domain_inside ? p.num_outer_loops : p.num_holes);
  p.min_angle_deg = detail::min_domain_angle_deg(g, lt.structure, &p.min_angle_vertex);
  p.lfs_min = detail::lfs_min(g, lt.triangulation);
  return p;
}

} // namespace pdd
