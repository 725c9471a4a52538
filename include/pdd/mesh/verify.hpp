/// \file verify.hpp
/// pdd::verify: checks a triangle mesh of a PSLG's domain against the correctness invariants
/// (Delaunay, orientation, conformity to the input segments, coverage of the domain area,
/// quality and size bounds) and reports every violation.
#pragma once

#include <pdd/concepts/sizing_field.hpp>
#include <pdd/core/point.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/geometry/validate.hpp>
#include <pdd/mesh/detail/verify_checks.hpp>
#include <pdd/mesh/quality_exemptions.hpp>
#include <pdd/mesh/verification_report.hpp>
#include <pdd/sizing/uniform.hpp>

#include <optional>

namespace pdd {

/// Verifies a mesh of the domain of d (dissertation sec. 1.1 requirements, DESIGN.md
/// "Correctness invariants"): every interior edge is locally Delaunay (exact
/// side_of_oriented_circle: the opposite apex is not strictly inside the circumcircle), or,
/// when o.criteria.encroachment is segment_encroachment::diametral_lens, every interior edge
/// not on an input segment (the mesh is constrained Delaunay, as Triangle's without -D); every
/// triangle is counter-clockwise and non-degenerate (exact orientation); no two vertices
/// coincide; every input segment is a union of mesh edges (a chain from the mesh vertex at
/// one endpoint to the one at the other through vertices on the segment, see
/// detail::verify_impl::on_segment_line), except, with domain_rule::triangle, a segment with no
/// domain face on either side (a dangling segment outside the domain or in a hole: left out of
/// the mesh, as Triangle does, like an isolated vertex there); every edge lies in at most two
/// triangles, interior edges in opposite directions, and boundary edges lie on input segments;
/// every isolated input vertex inside the domain is a vertex of a triangle; the triangle
/// areas sum to pdd::domain_area within o.area_tolerance; every triangle has its smallest angle
/// >= o.criteria.min_angle_deg - 1e-9 deg (unless exempt, see below) and its area <=
/// min(o.criteria.max_area, sizing.area_at(centroid)) * (1 + 1e-12). Input vertices are found in
/// the mesh by their coordinates, so any vertex numbering works.
///
/// With default options d is the PSLG the user gave pdd::generate, and verify decides what
/// generate decided: the domain's faces as generate reads them (pdd::domain_as_generated,
/// unless o.rule_as_given), and the triangles exempt from the angle bound by pdd's one rule
/// (pdd::quality_exemptions, unless o.quality_exempt is given): the verdict of `pdd-mesh
/// --verify`, pdd-verify, the Python module and the fuzz target, which all call it so.
/// \tparam S a SizingField. \throws geometry_error as pdd::validate (d must be valid).
/// Complexity O(n) expected (hashing, bucket sort of edges, segment walks over incident edges)
/// plus O(n_d log n_d) for the PSLG's faces; the triangle and edge checks run in parallel (TBB).
/// The report is the same for any number of threads. Thread-safe.
template <SizingField S>
verification_report verify(const triangle_mesh& m, const pslg& d, const verify_options& o,
                           const S& sizing) {
  const auto bound_at = [&](const point& p) { return static_cast<double>(sizing.area_at(p)); };
  std::optional<pslg> read; // the faces as generate read them, unless o.rule_as_given
  if (!o.rule_as_given) read = domain_as_generated(d);
  const pslg& domain = read ? *read : d;
  if (o.quality_exempt) return detail::verify_run(m, domain, o, bound_at);
  verify_options resolved = o;
  resolved.quality_exempt = find_quality_exempt_triangles(m, domain, o.criteria.min_angle_deg);
  return detail::verify_run(m, domain, resolved, bound_at);
}

/// Verifies a mesh against the criteria alone (area bound o.criteria.max_area). \see verify
inline verification_report verify(const triangle_mesh& m, const pslg& d,
                                  const verify_options& o = {}) {
  return verify(m, d, o, uniform_sizing{});
}

} // namespace pdd
