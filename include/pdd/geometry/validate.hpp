/// \file validate.hpp
/// pdd::validate: checks that a PSLG describes a domain pdd can mesh (Triangle's rule: any
/// planar straight-line graph whose segments meet only at shared endpoints, with hole points
/// inside the faces they remove).
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/geometry/detail/pslg_faces.hpp>
#include <pdd/geometry/detail/validate.hpp>
#include <pdd/geometry/loops.hpp>

namespace pdd {

/// Options of validate().
struct validate_options {
  /// Find the faces of the domain and check the hole points against them (a hole point on a
  /// vertex or segment or outside every segment, or no face left, is an error). When false,
  /// only the vertices and segments are checked (for tools that inspect any PSLG).
  bool check_domain = true;
};

namespace detail {
/// validate(), also returning the labelled faces (when check_domain) so that callers such as
/// analyze() and the pipeline build the triangulation once.
inline void validate_into(const pslg& g, const validate_options& opt, pslg_faces* out) {
  check_coordinates(g);
  const segment_incidence inc = incident_segments(g); // index range, zero length
  check_duplicate_vertices(g);
  check_duplicate_segments(g);
  check_intersections(g);
  if (!opt.check_domain) return;
  pslg_faces local;
  find_faces_into(g, out ? *out : local);
}
} // namespace detail

/// Checks that a PSLG describes a domain pdd can mesh, by Triangle's rule whatever g.rule
/// says: the faces of the arrangement of its segments are the domain except the unbounded face
/// (reachable from infinity without crossing a segment) and every face reached from a hole
/// point without crossing a segment. Vertices of any degree are accepted: loops that touch at
/// pinch vertices, internal constraint segments between two faces of the domain, dangling
/// segments ending inside a face, isolated vertices (inside a face they become mesh vertices;
/// elsewhere they are left out of the mesh), loops nested without a hole point (internal
/// boundaries: both sides are meshed).
///
/// Rejects, in this order: fewer than 3 vertices; non-finite coordinates (vertices, hole and
/// region points); segments referring to missing vertices; zero-length segments (a == b);
/// duplicate vertices (exactly equal coordinates); duplicate segments (same endpoints in
/// either order); segments that cross, overlap, or touch in their interior (a vertex on
/// another segment); then, with check_domain: all vertices collinear; hole points on a
/// vertex, on a segment or in the unbounded face; a PSLG with no face left in the domain.
/// \throws geometry_error whose message names the offending ids and coordinates; ids()
///   holds them (vertices, segments or hole points as the message says; for a vertex touching
///   a segment: {vertex, segment}). The first problem found is reported; among
///   intersections, the pair with the smallest segment ids.
/// Complexity O(n log^2 n + K) (K: segment pairs with overlapping bounding boxes) for the
/// intersection test, O(n log n) expected for the faces; thread-safe.
inline void validate(const pslg& g, const validate_options& opt = {}) {
  detail::validate_into(g, opt, nullptr);
}

/// True when g (valid) is a domain of closed loops that pdd's decoupled pipeline (MADD,
/// shielding) takes: every vertex on exactly two segments, and a hole point in every region
/// inside an even number >= 2 of loops and in no other region (so Triangle's rule and odd
/// nesting agree). \throws geometry_error as validate(). Complexity O(n log n) expected.
inline bool has_closed_loops(const pslg& g) {
  detail::pslg_faces pf;
  detail::validate_into(g, {}, &pf);
  return pf.closed_loops;
}

/// g as pdd::generate reads a user's PSLG: by Triangle's rule (domain_rule::triangle) unless it
/// is one of closed loops (has_closed_loops; both rules agree there and g.rule is kept). What
/// pdd::verify checks a mesh against by default, so that it and generate take the same faces
/// for the domain and the same segments for its constraints.
/// \throws geometry_error as validate(). Complexity O(n log n) expected.
inline pslg domain_as_generated(pslg g) {
  if (g.rule != domain_rule::triangle && !has_closed_loops(g)) g.rule = domain_rule::triangle;
  return g;
}

} // namespace pdd
