/// \file triangulate.hpp
/// pdd::triangle::triangulate: Triangle's `triangulate(switches, in, out)` on a pdd::pslg,
/// with pdd's decoupled pipeline (pdd::generate) doing the meshing. The module sits beside
/// pipeline/generate (it includes them); pdd-triangle and the Python `pdd.triangulate` use it.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/errors.hpp>
#include <pdd/geometry/validate.hpp>
#include <pdd/io/previous_mesh.hpp>
#include <pdd/mesh/region_attributes.hpp>
#include <pdd/triangle/detail/boundary_markers.hpp>
#include <pdd/triangle/detail/check.hpp>
#include <pdd/triangle/detail/edge_tables.hpp>
#include <pdd/triangle/detail/mesh_tables.hpp>
#include <pdd/triangle/detail/point_set_mesh.hpp>
#include <pdd/triangle/detail/pslg_mesh.hpp>
#include <pdd/triangle/detail/refine.hpp>
#include <pdd/triangle/detail/second_order.hpp>
#include <pdd/triangle/detail/vertex_attributes.hpp>
#include <pdd/triangle/switches.hpp>
#include <pdd/triangle/triangulation.hpp>

#include <array>
#include <optional>
#include <utility>
#include <vector>

namespace pdd::triangle {

namespace detail {
/// The tables after meshing: vertex attributes (the input's, interpolated by `attributes` at
/// new vertices), j, then n, e, v and o2 on the final mesh.
inline void finish_tables(triangulation& out, const switches& sw,
                          const vertex_attribute_interpolator* attributes) {
  std::vector<double>* per_vertex = nullptr;
  if (attributes) {
    out.vertex_attributes = attributes->at(out.mesh.vertices);
    out.vertex_attribute_count = attributes->count();
    per_vertex = &out.vertex_attributes;
  }
  const std::size_t width = out.vertex_attribute_count;
  if (sw.jettison) out.jettisoned_vertices = jettison_unused_vertices(out.mesh, per_vertex, width);
  if (!sw.neighbors && !sw.edges && !sw.voronoi && !sw.second_order) return;
  std::vector<std::array<long long, 3>> nb = triangle_neighbors(out.mesh);
  if (sw.edges || sw.voronoi)
    out.edges = list_edges(out.mesh, nb, sw.voronoi ? &out.voronoi : nullptr);
  if (sw.voronoi) out.voronoi.vertices = circumcentres(out.mesh);
  if (sw.second_order) out.second_order = add_second_order_nodes(out.mesh, nb, per_vertex, width);
  if (sw.neighbors) out.neighbors = std::move(nb);
}
/// What Triangle marks the output from (apply_boundary_markers): the input's vertices and
/// vertex markers as given (before c) and, with p, its segments (Triangle reads them only then).
inline pslg marking_input(const pslg& in, const switches& sw) {
  pslg marks;
  marks.vertices = in.vertices;
  marks.vertex_markers = in.vertex_markers;
  if (sw.poly) marks.segments = in.segments;
  return marks;
}

/// Meshes `domain` (prepared: O and c applied) as triangulate does; a PSLG (p) that encloses no
/// domain gives Triangle's empty mesh of `marks`' vertices (empty_triangulation).
inline triangulation mesh_input(pslg domain, const pslg& marks, const switches& sw,
                                const triangulate_options& o) {
  if (!sw.poly) return triangulate_point_set(domain, sw, o);
  try {
    return triangulate_pslg(std::move(domain), sw, o);
  } catch (const empty_domain_error& e) {
    return empty_triangulation(marks, e.what());
  }
}

/// The steps after meshing, in Triangle's order: C's check (against `checked`; null for a
/// vertex set), the boundary markers from `marks`, then finish_tables.
inline void finish_output(triangulation& out, const switches& sw, const pslg* checked,
                          const pslg& marks, const vertex_attribute_interpolator* attributes) {
  if (sw.check && !out.mesh.triangles.empty()) out.check = check_mesh(out, checked, sw);
  apply_boundary_markers(out.mesh, marks);
  finish_tables(out, sw, attributes);
}
} // namespace detail

/// Meshes `domain` as `triangle -<sw>` would mesh it, with pdd's pipeline.
///
/// Without p the input is a vertex set (its segments, holes and regions are not read, as in
/// Triangle): the result is the Delaunay triangulation of its distinct vertices (CGAL's
/// Delaunay_triangulation_2; no Steiner point), covering their convex hull; with q or a, a
/// quality mesh of that hull (closed by segments of marker 1; the inner vertices are isolated
/// vertices of the PSLG, kept as mesh vertices) by pdd::generate. A vertex equal to an earlier one
/// keeps its id but no triangle uses it (triangulation::duplicate_vertices: Triangle ignores it
/// with a warning); hull vertices of marker 0 get marker 1; with c the hull's edges are the
/// result's segments (mesh.segments holds them in every case).
///
/// With p and neither q nor a: the constrained Delaunay triangulation of the PSLG, no Steiner
/// point, as Triangle's bare -p (detail::constrained_delaunay). With p and q or a, a quality mesh:
/// q[angle], a[area], a alone (the regions' area bounds), A (regional attributes), O
/// (the hole points are dropped: the holes are then meshed, internal boundaries, as in
/// Triangle), c (the convex hull of the vertices closed by segments of marker 1 and meshed
/// whole, holes still carved). In both cases: j (drop unused vertices), n (the neighbour
/// table), e (every edge with its marker), v (the Voronoi diagram of the mesh's triangles:
/// circumcentres and the duals of the edges), o2 (a node in the middle of every edge, after the
/// mesh's vertices: triangulation::second_order). Q, V, N, E, P, B, I and z concern files and
/// printing: the caller (pdd-triangle, the Python module) honours them; i, F, l,
/// s, L, X choose Triangle's internal algorithms and change nothing here.
///
/// With D (conforming Delaunay), or S (at most max_steiner Steiner points) with q or a, the
/// whole domain is meshed on one CGAL triangulation instead of by pdd::generate
/// (detail::conforming_mesh: every triangle Delaunay against every vertex with D, segment
/// pieces and the vertices on them with their segment's marker); S without q, a or D adds
/// nothing, as in Triangle.
///
/// The domain with p is Triangle's (pdd::validate): every face of the segments' arrangement not
/// reachable from infinity or from a hole point without crossing a segment; internal and
/// dangling segments are mesh edges and isolated vertices inside the domain mesh vertices.
/// Differences from Triangle: on a domain of closed loops (pdd::has_closed_loops) a
/// region is a connected component of the domain; when regional area bounds differ between
/// components, each component is meshed by its own pdd::generate run (the components share
/// no segment, so the union is conforming). On any other domain (meshed whole by the
/// pipeline) a region labels its face: one run with the regional bounds as a sizing field
/// (pdd::regional_sizing: the smallest bound among a face's region points, where Triangle
/// takes the last), attributes per face (detail::mesh_face_regions).
/// A PSLG that encloses no domain (pdd::empty_domain_error: no face enclosed by segments, every
/// enclosed face eaten by hole points, all vertices collinear) gives Triangle's empty mesh: the
/// input's vertices, no triangle, no segment, and triangulation::empty_domain says why.
///
/// Boundary markers are Triangle's (detail::apply_boundary_markers): a vertex keeps its nonzero
/// input marker, else takes a nonzero marker of a segment it lies on, else 1 on the boundary of
/// the triangulation, else 0; an edge on a segment keeps its nonzero marker, else 1 on the
/// boundary, else 0. With C the mesh is checked by pdd::verify (triangulation::check; see
/// detail::check_mesh) before j, o2 and the tables.
/// \throws pdd::geometry_error for an invalid domain (after O and c), for a vertex set (or with
///   c a PSLG) of fewer than three distinct vertices or all collinear; everything
///   pdd::generate throws.
/// Vertex attributes of the input (pslg::vertex_attributes) are carried to every output vertex:
/// the input's own, linear interpolation over the input's constrained Delaunay triangulation
/// at new vertices (detail::vertex_attribute_interpolator), the edge's mean at o2's nodes.
/// Complexity: pdd::generate's (O(n log n) expected for a Delaunay triangulation), plus O(mesh)
/// for the tables. Thread-safety: reentrant.
inline triangulation triangulate(pslg domain, const switches& sw,
                                 const triangulate_options& o = {}) {
  // the attributes' source is triangulated once the domain is validated (by the meshing)
  pslg source;
  if (domain.vertex_attribute_count > 0) source = domain;
  const pslg marks = detail::marking_input(domain, sw);
  if (sw.poly) detail::prepare_pslg(domain, sw);
  std::optional<pslg> checked;
  if (sw.check && sw.poly) checked = domain;
  triangulation out = detail::mesh_input(std::move(domain), marks, sw, o);
  std::optional<detail::vertex_attribute_interpolator> attributes;
  if (source.vertex_attribute_count > 0 && out.empty_domain.empty())
    attributes.emplace(source, sw.poly);
  if (source.vertex_attribute_count > 0 && !out.empty_domain.empty()) {
    out.vertex_attributes = source.vertex_attributes; // no triangle: the input's own
    out.vertex_attribute_count = source.vertex_attribute_count;
  }
  detail::finish_output(out, sw, checked ? &*checked : nullptr, marks,
                        attributes ? &*attributes : nullptr);
  return out;
}

/// Refines a previous mesh as `triangle -r<sw>` does (its vertices kept, in their order, first):
/// the domain is what its triangles cover (its boundary edges segments of marker 1, its
/// segments kept with their markers; a hole wherever it has none), meshed by pdd::generate
/// with q[angle] and a[area]; with a bare a, its per-triangle area bounds (Triangle's .area, <=
/// 0: none) as a sizing field (pdd::background_mesh_sizing); without q or a, the constrained
/// Delaunay triangulation of its vertices and boundary. Its triangle attributes go to the new
/// triangles inside each old one, its vertex attributes are interpolated linearly in the old
/// triangles. j, n, e, v, o2 as in triangulate.
/// \throws pdd::geometry_error for ids out of range, counts that disagree, or a previous mesh
///   that is not a valid triangulation (pdd::validate); everything pdd::generate throws.
inline triangulation refine(const previous_mesh& m, const switches& sw,
                            const triangulate_options& o = {}) {
  triangulation out = detail::refine_previous(m, sw, o); // checks and validates m first
  std::optional<detail::vertex_attribute_interpolator> attributes;
  if (m.input.vertex_attribute_count > 0) {
    const pslg edges = detail::previous_triangulation(m); // its constrained triangulation
    validate(edges); // overlapping previous triangles: their edges cross
    attributes.emplace(edges, true);
  }
  std::optional<pslg> checked;
  switches checks = sw;
  checks.regional_areas = false; // the .area's bounds per previous triangle are not checked
  if (sw.check) checked = detail::previous_domain(m);
  detail::finish_output(out, checks, checked ? &*checked : nullptr, m.input,
                        attributes ? &*attributes : nullptr);
  return out;
}

} // namespace pdd::triangle
