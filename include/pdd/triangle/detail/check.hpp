/// \file check.hpp
/// Implementation of pdd::triangle::triangulate's switch C (pdd::verify on the mesh, against
/// what was meshed and the switches' bounds) and of its empty mesh for a PSLG that encloses no
/// domain (as Triangle's).
#pragma once

#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/mesh/verify.hpp>
#include <pdd/sizing/regional.hpp>
#include <pdd/triangle/detail/mesh_tables.hpp>
#include <pdd/triangle/switches.hpp>
#include <pdd/triangle/triangulation.hpp>

#include <limits>
#include <string>
#include <utility>

namespace pdd::triangle::detail {

/// Triangle's result for a PSLG that encloses no domain: the input's vertices with their
/// markers, no triangle, no segment; `why` says so (triangulation::empty_domain).
inline triangulation empty_triangulation(const pslg& in, std::string why) {
  triangulation out;
  out.mesh.vertices = in.vertices;
  out.mesh.vertex_markers = in.vertex_markers;
  out.mesh.vertex_markers.resize(in.vertices.size(), 0);
  out.empty_domain = std::move(why);
  return out;
}

/// The bounds switch C checks: q's angle and a's uniform area (neither with S, whose budget may
/// stop refinement short of them), and which edges must be Delaunay (every interior edge with
/// D, the edges off the input segments otherwise: the mesh is constrained Delaunay, as
/// Triangle's).
inline verify_options check_options(const switches& sw) {
  verify_options o;
  const bool bounded = sw.quality && sw.max_steiner < 0;
  o.criteria.min_angle_deg = bounded ? sw.min_angle_deg : 0.0;
  o.criteria.max_area =
      bounded && sw.max_area > 0.0 ? sw.max_area : std::numeric_limits<double>::infinity();
  o.criteria.encroachment =
      sw.conforming ? segment_encroachment::diametral_circle : segment_encroachment::diametral_lens;
  return o;
}

/// The domain a mesh of a vertex set (no p) is checked against: the mesh's vertices and its
/// hull's edges (mesh.segments) as segments.
inline pslg hull_domain(const triangle_mesh& m) {
  pslg g;
  g.vertices = m.vertices;
  g.vertex_markers.assign(m.vertices.size(), 0);
  for (const mesh_edge& e : m.segments)
    g.add_segment(e.a, e.b, e.marker);
  return g;
}

/// Switch C: pdd::verify on t.mesh against `domain` (what was meshed: the PSLG after O and c;
/// for a vertex set, pass nothing and the hull is taken), with check_options(sw) and, with a
/// bare a (and no S), the regions' area bounds. Equal vertices of a vertex set (used by no
/// triangle) are left out of the checked copy. \throws pdd::geometry_error as pdd::verify.
inline verification_report check_mesh(const triangulation& t, const pslg* domain,
                                      const switches& sw) {
  triangle_mesh copy;
  const triangle_mesh* m = &t.mesh;
  if (!t.duplicate_vertices.empty()) {
    copy = t.mesh;
    jettison_unused_vertices(copy);
    m = &copy;
  }
  const pslg hull = domain ? pslg{} : hull_domain(*m);
  const pslg& d = domain ? *domain : hull;
  const verify_options o = check_options(sw);
  if (!sw.regional_areas || sw.max_steiner >= 0 || d.regions.empty()) return verify(*m, d, o);
  pslg read = d;
  read.rule = domain_rule::triangle;
  return verify(*m, d, o, regional_sizing(read));
}

} // namespace pdd::triangle::detail
