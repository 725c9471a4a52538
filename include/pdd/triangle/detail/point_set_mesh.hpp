/// \file point_set_mesh.hpp
/// Implementation of pdd::triangle::triangulate without p (the input is a vertex set): the
/// Delaunay triangulation of its distinct vertices, or with q or a a quality mesh of their convex
/// hull (the hull a loop of segments, the inner vertices isolated vertices of that PSLG, meshed
/// by pdd::generate), numbered as Triangle numbers it.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/triangle/detail/mesh_tables.hpp>
#include <pdd/triangle/detail/point_set.hpp>
#include <pdd/triangle/detail/pslg_mesh.hpp>
#include <pdd/triangle/switches.hpp>
#include <pdd/triangle/triangulation.hpp>

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace pdd::triangle::detail {

/// Triangle's vertex markers on a vertex set: the input markers, 1 for the hull's vertices
/// whose marker is 0 (they lie on the boundary of the triangulation).
inline std::vector<int> point_set_markers(const pslg& in, const std::vector<index_t>& hull) {
  std::vector<int> markers = in.vertex_markers;
  markers.resize(in.vertices.size(), 0);
  for (const index_t h : hull)
    if (markers[h] == 0) markers[h] = 1;
  return markers;
}

/// The hull's edges as segments of marker 1 (Triangle's markhull), counter-clockwise.
inline std::vector<mesh_edge> hull_segments(const std::vector<index_t>& hull) {
  std::vector<mesh_edge> out;
  out.reserve(hull.size());
  for (std::size_t k = 0; k < hull.size(); ++k)
    out.push_back({hull[k], hull[(k + 1) % hull.size()], 1});
  return out;
}

/// The Delaunay triangulation itself: every input vertex (equal ones too, used by no triangle),
/// no Steiner point.
inline triangle_mesh delaunay_mesh(const pslg& in, const point_set_delaunay& d) {
  triangle_mesh m;
  m.vertices = in.vertices;
  m.vertex_markers = point_set_markers(in, d.hull);
  m.triangles = d.triangles;
  m.triangle_markers.assign(m.triangles.size(), 0);
  m.segments = hull_segments(d.hull);
  return m;
}

/// A quality mesh of the hull (switches q, a): the distinct vertices, the hull closed by
/// segments of marker 1, meshed by triangulate_pslg; then renumbered so that every input vertex
/// keeps its id (an equal vertex keeps its slot, used by no triangle) and the Steiner vertices
/// follow.
inline triangulation quality_point_set(const pslg& in, const distinct_vertices& dv,
                                       const point_set_delaunay& d, switches sw,
                                       const triangulate_options& o) {
  const std::vector<int> markers = point_set_markers(in, d.hull);
  std::vector<index_t> local(in.vertices.size(), no_index);
  pslg g;
  for (const index_t k : dv.kept)
    local[k] = g.add_vertex(in.vertices[k], markers[k]);
  for (const mesh_edge& e : hull_segments(d.hull))
    g.add_segment(local[e.a], local[e.b], e.marker);
  sw.poly = true;
  sw.convex = false; // the hull is closed already
  triangulation t = triangulate_pslg(std::move(g), sw, o);
  const std::size_t n = in.vertices.size(), steiner = t.mesh.vertices.size() - dv.kept.size();
  std::vector<index_t> new_id(t.mesh.vertices.size());
  for (std::size_t u = 0; u < new_id.size(); ++u)
    new_id[u] = u < dv.kept.size() ? dv.kept[u] : static_cast<index_t>(n + u - dv.kept.size());
  renumber_vertices(t.mesh, new_id, n + steiner);
  for (std::size_t i = 0; i < n; ++i)
    if (dv.first[i] != i) {
      t.mesh.vertices[i] = in.vertices[i];
      t.mesh.vertex_markers[i] = markers[i];
    }
  return t;
}

/// Triangulates the vertex set of `in` as `triangle -<sw>` without p does: its segments, holes
/// and regions are not read (Triangle reads them only with p).
/// \throws pdd::geometry_error for fewer than three distinct vertices or all collinear; what
///   triangulate_pslg throws with q or a.
inline triangulation triangulate_point_set(const pslg& in, const switches& sw,
                                           const triangulate_options& o) {
  const distinct_vertices dv = find_distinct(in.vertices);
  const point_set_delaunay d = delaunay_of(in.vertices, dv.kept);
  triangulation out;
  if (sw.quality) {
    out = quality_point_set(in, dv, d, sw, o);
  } else {
    out.mesh = delaunay_mesh(in, d);
    if (sw.regional_attributes) out.triangle_attributes.assign(out.mesh.triangles.size(), 0.0);
  }
  for (std::size_t i = 0; i < dv.first.size(); ++i)
    if (dv.first[i] != i) out.duplicate_vertices.push_back({static_cast<index_t>(i), dv.first[i]});
  return out;
}

} // namespace pdd::triangle::detail
