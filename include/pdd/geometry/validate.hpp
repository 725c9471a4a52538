/// \file validate.hpp
/// pdd::validate: checks that a PSLG describes a domain pdd can mesh (closed, simple,
/// non-intersecting loops with hole points in the holes; Triangle's convention).
#pragma once

#include <pdd/geometry/detail/validate.hpp>
#include <pdd/geometry/loops.hpp>
#include <pdd/core/pslg.hpp>

namespace pdd {

/// Options of validate().
struct validate_options {
  /// Require every segment to lie on a closed loop (every vertex on exactly two segments)
  /// and check hole points against the loops. When false, dangling segments, internal
  /// constraints and isolated vertices pass, and hole points are not checked (pdd's
  /// pipeline needs closed loops; the option serves tools that only inspect a PSLG).
  bool require_closed_loops = true;
};

namespace detail {
/// validate(), also returning the loops and the labelled triangulation (when closed loops
/// are required) so that callers such as analyze() build the triangulation once.
inline void validate_into(const pslg& g, const validate_options& opt,
                          loops_with_triangulation* out) {
  check_coordinates(g);
  const segment_incidence inc = incident_segments(g); // index range, zero length
  check_duplicate_vertices(g);
  check_duplicate_segments(g);
  check_intersections(g);
  if (!opt.require_closed_loops) return;
  require_degree_two(g, inc);
  loops_with_triangulation local;
  loops_with_triangulation& lt = out ? *out : local;
  find_loops_into(g, lt);
  check_holes(g, lt);
}
} // namespace detail

/// Checks that a PSLG describes a domain pdd can mesh; the domain is the set of faces
/// enclosed by an odd number of loops, and each region enclosed by an even number >= 2 of
/// loops is a hole that must hold a hole point (Triangle's convention with closed loops).
///
/// Rejects, in this order: fewer than 3 vertices; non-finite coordinates (vertices, hole and
/// region points); segments referring to missing vertices; zero-length segments (a == b);
/// duplicate vertices (exactly equal coordinates); duplicate segments (same endpoints in
/// either order); segments that cross, overlap, or touch in their interior (a vertex on
/// another segment); then, with require_closed_loops: vertices on 1 or more than 2 segments
/// ("dangling segments and internal constraint segments are not supported yet"), isolated
/// vertices ("isolated vertices are not supported yet"); hole points on a segment, outside
/// every loop, or inside the meshed domain; loops enclosing a hole region without a hole
/// point ("internal boundaries are not supported yet").
/// \throws geometry_error whose message names the offending ids and coordinates; ids()
///   holds them (vertices, segments, hole points or loops as the message says; for a
///   vertex touching a segment: {vertex, segment}). The first problem found is reported;
///   among intersections, the pair with the smallest segment ids.
/// Complexity O(n log^2 n + K) (K: segment pairs with overlapping bounding boxes) for the
/// intersection test, O(n log n) expected for the loops; thread-safe.
inline void validate(const pslg& g, const validate_options& opt = {}) {
  detail::validate_into(g, opt, nullptr);
}

} // namespace pdd
