/// \file point_set_mesh.hpp
/// Implementation of pdd::triangle::triangulate without p (the input is a vertex set): the
/// Delaunay triangulation of its distinct vertices, or with q or a a quality mesh of their convex
/// hull (the hull a loop of segments, the inner vertices isolated vertices of that PSLG, meshed
/// by pdd::generate; with an area bound large enough for N > 1, decoupled into strips whose
/// separators run through the vertices, point_set_strips.hpp), numbered as Triangle numbers it.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/errors.hpp>
#include <pdd/generate.hpp>
#include <pdd/parallel/tbb_executor.hpp>
#include <pdd/pipeline/planning.hpp>
#include <pdd/triangle/detail/conforming_path.hpp>
#include <pdd/triangle/detail/mesh_tables.hpp>
#include <pdd/triangle/detail/point_set.hpp>
#include <pdd/triangle/detail/point_set_strips.hpp>
#include <pdd/triangle/detail/pslg_mesh.hpp>
#include <pdd/triangle/detail/regions.hpp>
#include <pdd/triangle/switches.hpp>
#include <pdd/triangle/triangulation.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <numbers>
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

/// How many strips the hull of a vertex set (v, its Delaunay triangulation d over `distinct`
/// vertices) is decoupled into for switches sw: 1 (meshed whole) without a uniform area bound,
/// with D or S, or when o.subdomains is 1; else o.subdomains, or with automatic N
/// pdd::automatic_subdomains of the estimate (pdd::estimate_triangles on the hull's area); at
/// most the longer side of the bounding box over 12 vertex spacings (sqrt(area / distinct)), so
/// that a strip's band (0.35 of its width each side of its line) holds a path of Gabriel edges
/// (at 6 spacings nearly every path of a million random vertices failed).
inline std::size_t strip_count(const std::vector<point>& v, std::size_t distinct,
                               const point_set_delaunay& d, const switches& sw,
                               const triangulate_options& o) {
  if (sw.max_area <= 0.0 || sw.regional_areas || conforming_path(sw) || o.subdomains == 1) return 1;
  double twice = 0.0, x0 = v[d.hull[0]].x, x1 = x0, y0 = v[d.hull[0]].y, y1 = y0;
  for (std::size_t k = 0; k < d.hull.size(); ++k) {
    const point a = v[d.hull[k]], b = v[d.hull[(k + 1) % d.hull.size()]];
    twice += a.x * b.y - a.y * b.x;
    x0 = std::min(x0, a.x), x1 = std::max(x1, a.x), y0 = std::min(y0, a.y), y1 = std::max(y1, a.y);
  }
  const double area = 0.5 * twice, spacing = std::sqrt(area / static_cast<double>(distinct));
  const auto most = static_cast<std::size_t>(std::max(x1 - x0, y1 - y0) / (12.0 * spacing));
  mesh_criteria c;
  c.max_area = sw.max_area;
  const std::size_t n =
      o.subdomains != 0
          ? o.subdomains
          : automatic_subdomains(estimate_triangles(area, c), tbb_executor{o.threads}.concurrency(),
                                 planning_options{});
  return std::min(n, most);
}

/// The hull's PSLG `strips` (its separators segments of marker 0) meshed by pdd::generate in
/// n subdomains, one per strip, decoupled with k = (1/2) sqrt(A / sqrt 2), Theorem 15's area
/// term: the vertices' own small distances do not shorten the separator pieces (their disks
/// hold no vertex: Gabriel edges), and an invariance repair halves k where a kernel split a
/// piece all the same. The separators' edges are left out of the mesh's segments (Triangle's
/// segments of a vertex set are the hull's).
inline triangulation mesh_strips(pslg strips, std::size_t n, const switches& sw,
                                 const triangulate_options& o) {
  generate_options gopt = options_for(sw, o);
  gopt.subdomains = n;
  gopt.decoupling.k_override = 0.5 * std::sqrt(gopt.criteria.max_area / std::numbers::sqrt2);
  triangulation out = generated(strips, gopt, sw);
  std::erase_if(out.mesh.segments, [](const mesh_edge& e) { return e.marker == 0; });
  input_vertices_first(out.mesh, strips);
  out.strips = n;
  return out;
}

/// The PSLG of a strip plan on the hull PSLG g (its vertex k is input vertex dv.kept[k],
/// local[i] is input vertex i's id in g): g's vertices, then the cut ends that are not hull
/// vertices (Steiner vertices of marker 1), the hull's edges split at them (marker 1), the
/// separators (marker 0).
inline pslg strip_pslg(const pslg& g, const std::vector<index_t>& local,
                       const point_set_delaunay& d, const strip_plan& plan, std::size_t inputs) {
  pslg s;
  s.vertices = g.vertices;
  s.vertex_markers = g.vertex_markers;
  std::vector<index_t> end_id(plan.ends.size());
  std::map<std::pair<index_t, index_t>, std::vector<index_t>> on_edge; // Steiner ends by edge
  for (std::size_t k = 0; k < plan.ends.size(); ++k) {
    const cut_end& e = plan.ends[k];
    end_id[k] = e.vertex != no_index ? local[e.vertex] : s.add_vertex(e.at, 1);
    if (e.vertex == no_index) on_edge[{e.a, e.b}].push_back(static_cast<index_t>(k));
  }
  for (std::size_t k = 0; k < d.hull.size(); ++k) {
    const index_t a = d.hull[k], b = d.hull[(k + 1) % d.hull.size()];
    std::vector<index_t> chain = on_edge[{a, b}]; // ends, ordered from a
    const auto from_a = [&](index_t e) {
      return std::hypot(plan.ends[e].at.x - g.vertices[local[a]].x,
                        plan.ends[e].at.y - g.vertices[local[a]].y);
    };
    std::sort(chain.begin(), chain.end(),
              [&](index_t x, index_t y) { return from_a(x) < from_a(y); });
    index_t last = local[a];
    for (const index_t e : chain) {
      s.add_segment(last, end_id[e], 1);
      last = end_id[e];
    }
    s.add_segment(last, local[b], 1);
  }
  const auto id = [&](index_t x) { return x < inputs ? local[x] : end_id[x - inputs]; };
  for (const auto& path : plan.paths)
    for (std::size_t i = 0; i + 1 < path.size(); ++i)
      s.add_segment(id(path[i]), id(path[i + 1]), 0);
  return s;
}

/// The hull PSLG g of the vertex set `in` (its vertex k is input vertex dv.kept[k]) meshed:
/// in strips (strip_count > 1; when strip_separators finds no path for some cut, half as many
/// strips, down to 2; a decomposition or decoupling failure, or strips that are no valid PSLG
/// (an end's perpendicular crossing a path, not seen), fall back to the whole hull),
/// else whole by triangulate_pslg. The cut ends follow the distinct input vertices in the
/// result's vertices, as Steiner vertices.
inline triangulation mesh_hull(pslg g, const pslg& in, const distinct_vertices& dv,
                               const std::vector<index_t>& local, const point_set_delaunay& d,
                               const switches& sw, const triangulate_options& o) {
  const double k = 0.5 * std::sqrt(sw.max_area / std::numbers::sqrt2); // see mesh_strips
  strip_plan plan;
  std::size_t n = strip_count(in.vertices, dv.kept.size(), d, sw, o);
  for (; n > 1 && plan.paths.empty(); n = n > 2 ? n / 2 : 1)
    plan = strip_separators(in.vertices, dv.kept, d, n, 2.0 * k / std::numbers::sqrt3);
  if (!plan.paths.empty()) {
    try {
      return mesh_strips(strip_pslg(g, local, d, plan, in.vertices.size()), plan.paths.size() + 1,
                         sw, o);
    } catch (const decomposition_error&) {
    } catch (const decoupling_error&) {
    } catch (const geometry_error&) { // an end's perpendicular crossing a path: no strips
    }
  }
  return triangulate_pslg(std::move(g), sw, o);
}

/// A quality mesh of the hull (switches q, a): the distinct vertices, the hull closed by
/// segments of marker 1, meshed by mesh_hull; then renumbered so that every input vertex
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
  triangulation t = mesh_hull(std::move(g), in, dv, local, d, sw, o);
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
