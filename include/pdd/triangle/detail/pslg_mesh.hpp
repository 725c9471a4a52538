/// \file pslg_mesh.hpp
/// Implementation of pdd::triangle::triangulate with p: the PSLG (with c, its vertices' convex
/// hull closed by segments first) triangulated without Steiner points, or meshed by
/// pdd::generate for q and a, the regional paths, Triangle's numbering of the vertices.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/generate.hpp>
#include <pdd/geometry/validate.hpp>
#include <pdd/sizing/regional.hpp>
#include <pdd/triangle/detail/conforming.hpp>
#include <pdd/triangle/detail/constrained_delaunay.hpp>
#include <pdd/triangle/detail/face_regions.hpp>
#include <pdd/triangle/detail/mesh_tables.hpp>
#include <pdd/triangle/detail/point_set.hpp>
#include <pdd/triangle/detail/regions.hpp>
#include <pdd/triangle/switches.hpp>
#include <pdd/triangle/triangulation.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace pdd::triangle::detail {

/// Switch c with p: closes the convex hull of the PSLG's vertices with segments of marker 1
/// (Triangle's markhull); a hull edge that is already a segment keeps it (marker 0 becomes 1),
/// and hull vertices of marker 0 get 1 (they lie on a segment of marker 1). Equal vertices are
/// left to validate() to report.
/// \throws pdd::geometry_error when the vertices are fewer than three or all collinear.
inline void close_convex_hull(pslg& g) {
  const point_set_delaunay d = delaunay_of(g.vertices, find_distinct(g.vertices).kept);
  std::unordered_map<std::uint64_t, std::size_t> segment_of;
  for (std::size_t s = 0; s < g.segments.size(); ++s)
    segment_of.emplace(edge_key(g.segments[s].a, g.segments[s].b), s);
  if (g.vertex_markers.size() != g.vertices.size()) g.vertex_markers.resize(g.vertices.size(), 0);
  for (std::size_t k = 0; k < d.hull.size(); ++k) {
    const index_t a = d.hull[k], b = d.hull[(k + 1) % d.hull.size()];
    if (g.vertex_markers[a] == 0) g.vertex_markers[a] = 1;
    const auto it = segment_of.find(edge_key(a, b));
    if (it == segment_of.end())
      g.add_segment(a, b, 1);
    else if (g.segments[it->second].marker == 0)
      g.segments[it->second].marker = 1;
  }
}

/// Switch D, or S with q or a: the whole domain on one triangulation (conforming_mesh), with a
/// alone the regions' area bounds (pdd::regional_sizing, as mesh_face_regions).
inline triangulation conforming_pslg(pslg domain, const switches& sw) {
  any_sizing sizing;
  if (sw.regional_areas && !domain.regions.empty()) {
    domain.rule = domain_rule::triangle;
    regional_sizing field(domain);
    if (field.bounded_regions() > 0) sizing = std::move(field);
  }
  return conforming_mesh(std::move(domain), sw, sizing);
}

/// Switches O (the hole points dropped) and c (the convex hull closed, close_convex_hull) on a
/// PSLG before it is meshed.
inline void prepare_pslg(pslg& domain, const switches& sw) {
  if (sw.ignore_holes) domain.holes.clear();
  if (sw.convex) close_convex_hull(domain);
}

/// One pdd::generate run of `domain` as a triangulation: the mesh, the run's statistics and,
/// with A, every triangle's attribute 0 (no region). Its vertices are the generator's order.
inline triangulation generated(const pslg& domain, const generate_options& gopt,
                               const switches& sw) {
  generate_result r = generate(domain, gopt);
  triangulation out;
  out.mesh = std::move(r.mesh);
  out.runs.push_back(std::move(r.statistics));
  if (sw.regional_attributes) out.triangle_attributes.assign(out.mesh.triangles.size(), 0.0);
  return out;
}

/// Meshes a PSLG (after prepare_pslg) as `triangle -p<sw>` would (see triangulate): without q
/// or a its constrained Delaunay triangulation, with them pdd's pipeline, with D (or S and q
/// or a) one triangulation (conforming_pslg); the input vertices come first in the result, in
/// input order.
inline triangulation triangulate_pslg(pslg domain, const switches& sw,
                                      const triangulate_options& o) {
  if (conforming_path(sw)) return conforming_pslg(std::move(domain), sw);
  if (!sw.quality) return constrained_delaunay(std::move(domain), sw); // no Steiner point
  const bool closed_loops = has_closed_loops(domain);                  // validates
  const generate_options gopt = options_for(sw, o);
  triangulation out;
  const bool regional = !domain.regions.empty() && (sw.regional_areas || sw.regional_attributes);
  if (regional && !closed_loops) {
    mesh_face_regions(domain, sw, gopt, out);
  } else if (regional) {
    mesh_regions(domain, sw, gopt, out);
  } else {
    out = generated(domain, gopt, sw);
  }
  input_vertices_first(out.mesh, domain);
  return out;
}

} // namespace pdd::triangle::detail
