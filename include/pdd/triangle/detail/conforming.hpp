/// \file conforming.hpp
/// Implementation of pdd::triangle::triangulate for switches D (conforming Delaunay) and S (a
/// Steiner point budget): the whole domain on one CGAL constrained Delaunay triangulation, not
/// pdd::generate. The decoupled engine's subdomains meet at interface edges that are only
/// constrained Delaunay (a vertex across an interface may lie in the circumcircle of a triangle
/// beside it), so their union is not guaranteed to be Delaunay; and a budget of Steiner points
/// cannot be shared out between subdomains before they are meshed. Without q or a, D is
/// CGAL::make_conforming_Delaunay_2 (segments split until every edge is locally Delaunay); with
/// q or a, CGAL::Delaunay_mesher_2, whose segment test is Gabriel on both sides of every
/// segment (an empty diametral circle: every segment then is a Delaunay edge, so the mesh is
/// conforming Delaunay). S stops either one, step by step, after its number of points.
#pragma once

#include <pdd/triangle/detail/conforming_path.hpp>

#ifdef PDD_PERMISSIVE
#include <pdd/triangle/detail/conforming_refused.hpp>
#else

#include <pdd/core/kernel.hpp>
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/errors.hpp>
#include <pdd/geometry/validate.hpp>
#include <pdd/kernels/cgal/criteria.hpp>
#include <pdd/mesh/region_attributes.hpp>
#include <pdd/sizing/any_sizing.hpp>
#include <pdd/triangle/detail/mesh_tables.hpp>
#include <pdd/triangle/switches.hpp>
#include <pdd/triangle/triangulation.hpp>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Triangulation_conformer_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace pdd::triangle::detail::conforming {

/// A vertex's id in the output: the input index, or no_index for a Steiner vertex until
/// numbered.
struct vertex_id {
  index_t id = no_index;
};

using vertex_base = CGAL::Triangulation_vertex_base_with_info_2<vertex_id, epick>;
using tds =
    CGAL::Triangulation_data_structure_2<vertex_base, CGAL::Delaunay_mesh_face_base_2<epick>>;
/// No constraint may cross another (the domain is validated first).
using cdt =
    CGAL::Constrained_Delaunay_triangulation_2<epick, tds, CGAL::No_constraint_intersection_tag>;
using face_handle = cdt::Face_handle;

/// The vertices (with their input ids) and the segments of a valid PSLG.
inline void build(cdt& tr, const pslg& g) {
  std::vector<std::pair<epick::Point_2, vertex_id>> pts;
  pts.reserve(g.vertices.size());
  for (std::size_t i = 0; i < g.vertices.size(); ++i)
    pts.emplace_back(epick::Point_2(g.vertices[i].x, g.vertices[i].y),
                     vertex_id{static_cast<index_t>(i)});
  tr.insert(pts.begin(), pts.end()); // spatially sorted
  std::vector<cdt::Vertex_handle> vh(g.vertices.size());
  for (auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
    vh[v->info().id] = v;
  for (const segment& s : g.segments)
    tr.insert_constraint(vh[s.a], vh[s.b]);
}

/// Marks out of the domain every face reachable from f without crossing a constraint.
inline void flood_out(face_handle f) {
  std::vector<face_handle> stack{f};
  f->set_in_domain(false);
  while (!stack.empty()) {
    const face_handle g = stack.back();
    stack.pop_back();
    for (int i = 0; i < 3; ++i)
      if (!g->is_constrained(i) && g->neighbor(i)->is_in_domain()) {
        g->neighbor(i)->set_in_domain(false);
        stack.push_back(g->neighbor(i));
      }
  }
}

/// Triangle's rule: every face but those reachable from infinity or from a hole point without
/// crossing a segment.
inline void mark_domain(cdt& tr, const std::vector<point>& holes) {
  for (auto f = tr.all_faces_begin(); f != tr.all_faces_end(); ++f)
    f->set_in_domain(true);
  flood_out(tr.infinite_face());
  for (const point& h : holes) {
    const face_handle f = tr.locate(epick::Point_2(h.x, h.y));
    if (f != face_handle() && !tr.is_infinite(f) && f->is_in_domain()) flood_out(f);
  }
}

/// True when a face of the domain lies on either side of edge i of f.
inline bool touches_domain(const cdt& tr, face_handle f, int i) {
  const face_handle n = f->neighbor(i);
  return (!tr.is_infinite(f) && f->is_in_domain()) || (!tr.is_infinite(n) && n->is_in_domain());
}

/// Drops the segments with no domain face on either side (Triangle leaves them out of the mesh,
/// and they must not be split) and marks the domain again.
inline void release_outside_segments(cdt& tr, const std::vector<point>& holes) {
  std::vector<std::pair<cdt::Vertex_handle, cdt::Vertex_handle>> outside;
  for (auto e = tr.finite_edges_begin(); e != tr.finite_edges_end(); ++e)
    if (e->first->is_constrained(e->second) && !touches_domain(tr, e->first, e->second))
      outside.emplace_back(e->first->vertex(cdt::cw(e->second)),
                           e->first->vertex(cdt::ccw(e->second)));
  for (const auto& [a, b] : outside) {
    face_handle f;
    int i = 0;
    if (tr.is_edge(a, b, f, i)) tr.remove_constrained_edge(f, i);
  }
  if (!outside.empty()) mark_domain(tr, holes);
}

/// The most points a refinement for D or S may add before it is taken for one that does not end:
/// small input angles can keep a refinement that must leave every segment Delaunay (Gabriel)
/// splitting segments without end (Triangle's -D loops on such inputs too). A million, plus 64
/// per input vertex, plus 4 times the triangles the area bound alone asks for (the domain's area
/// over 0.656 max_area): far above what a mesh that ends needs.
inline long long runaway_cap(const cdt& tr, double max_area) {
  double area = 0.0;
  for (auto f = tr.finite_faces_begin(); f != tr.finite_faces_end(); ++f)
    if (f->is_in_domain())
      area += CGAL::area(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point());
  const double by_area = std::isfinite(max_area) ? 4.0 * area / (0.656 * max_area) : 0.0;
  const double cap = 1e6 + 64.0 * static_cast<double>(tr.number_of_vertices()) + by_area;
  return cap < 9e18 ? static_cast<long long>(cap) : std::numeric_limits<long long>::max();
}

/// Runs `step` (one point per call, false when done) at most `budget` times (negative: until
/// done), stopping with pdd::limit_error at `cap` points when the budget does not stop it first.
template <class Step>
void run_steps(Step step, long long budget, long long cap, const char* what) {
  const long long limit = budget < 0 ? cap : std::min(budget, cap);
  long long added = 0;
  while (added < limit && step())
    ++added;
  if (added == cap && (budget < 0 || budget > cap) && step())
    throw limit_error("the refinement for " + std::string(what) + " did not end: it added " +
                      std::to_string(cap) +
                      " points, far more than the mesh needs (see runaway_cap). Small input "
                      "angles keep a refinement that must leave every segment Delaunay "
                      "splitting segments without end; mesh without D, or cap the points with S");
}

/// Switch D without q or a: the segments split (CGAL::Triangulation_conformer_2) until every
/// constrained edge is locally Delaunay, at most `budget` points (negative: no limit) and never
/// past runaway_cap.
inline void make_conforming(cdt& tr, long long budget) {
  const long long cap = runaway_cap(tr, std::numeric_limits<double>::infinity());
  CGAL::Triangulation_conformer_2<cdt> conform(tr);
  conform.init_Delaunay();
  run_steps([&] { return conform.step_by_step_conforming_Delaunay(); }, budget, cap, "-D");
}

/// q or a (with D or S): CGAL::Delaunay_mesher_2 on the marked domain under the angle bound,
/// max_area and the sizing field, at most `budget` points (negative: no limit) and never past
/// runaway_cap.
inline void refine(cdt& tr, const mesh_criteria& c, const any_sizing& sizing, long long budget) {
  using criteria = pdd::cgal::sizing_criteria<cdt, any_sizing>;
  const long long cap = runaway_cap(tr, c.max_area);
  CGAL::Delaunay_mesher_2<cdt, criteria> mesher(tr, criteria(c.shape_bound(), c.max_area, sizing));
  mesher.init(true); // the domain is marked already
  run_steps([&] { return mesher.step_by_step_refine_mesh(); }, budget, cap, "-D or -S");
}

/// The marker of every Steiner vertex on a segment (indexed by output id - n; 0 elsewhere):
/// the Steiner vertices of one input segment form a path of constrained edges between its two
/// input endpoints, whose segment gives the marker. `along[v - n]` holds the (at most two)
/// constrained neighbours of Steiner vertex v.
inline std::vector<int> steiner_markers(const std::vector<std::array<index_t, 2>>& along,
                                        std::size_t n,
                                        const std::unordered_map<std::uint64_t, int>& marker_of) {
  std::vector<int> marker(along.size(), 0);
  std::vector<char> done(along.size(), 0);
  std::vector<index_t> path;
  for (std::size_t s = 0; s < along.size(); ++s) {
    if (done[s] || along[s][0] == no_index) continue;
    std::array<index_t, 2> ends{};
    path.assign(1, static_cast<index_t>(n + s));
    for (int dir = 0; dir < 2; ++dir) {
      index_t prev = static_cast<index_t>(n + s), cur = along[s][dir];
      while (cur != no_index && cur >= n) {
        path.push_back(cur);
        const auto& nb = along[cur - n];
        const index_t next = nb[0] == prev ? nb[1] : nb[0];
        prev = cur;
        cur = next;
      }
      ends[dir] = cur;
    }
    PDD_ASSERT(ends[0] != no_index && ends[1] != no_index);
    const auto it = marker_of.find(edge_key(ends[0], ends[1]));
    for (const index_t v : path) {
      done[v - n] = 1;
      marker[v - n] = it == marker_of.end() ? 0 : it->second;
    }
  }
  return marker;
}

/// The constrained edges that touch the domain as m.segments (sorted, a < b) with the markers of
/// their input segments, and the markers of the Steiner vertices on them.
inline void extract_segments(const cdt& tr, const pslg& g, triangle_mesh& m) {
  const std::size_t n = g.vertices.size();
  std::unordered_map<std::uint64_t, int> marker_of;
  for (const segment& s : g.segments)
    marker_of.emplace(edge_key(s.a, s.b), s.marker);
  std::vector<std::array<index_t, 2>> along(m.vertices.size() - n, {no_index, no_index});
  const auto link = [&](index_t v, index_t w) {
    if (v >= n) along[v - n][along[v - n][0] == no_index ? 0 : 1] = w;
  };
  for (auto e = tr.finite_edges_begin(); e != tr.finite_edges_end(); ++e) {
    if (!e->first->is_constrained(e->second)) continue;
    const index_t a = e->first->vertex(cdt::cw(e->second))->info().id;
    const index_t b = e->first->vertex(cdt::ccw(e->second))->info().id;
    link(a, b);
    link(b, a);
    if (touches_domain(tr, e->first, e->second))
      m.segments.push_back({std::min(a, b), std::max(a, b), 0});
  }
  const std::vector<int> steiner = steiner_markers(along, n, marker_of);
  for (std::size_t s = 0; s < steiner.size(); ++s)
    m.vertex_markers[n + s] = steiner[s];
  for (mesh_edge& e : m.segments)
    if (e.b >= n) {
      e.marker = steiner[e.b - n];
    } else if (const auto it = marker_of.find(edge_key(e.a, e.b)); it != marker_of.end()) {
      e.marker = it->second;
    }
  std::sort(m.segments.begin(), m.segments.end(), [](const mesh_edge& x, const mesh_edge& y) {
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
}

/// The mesh: the input vertices first, in input order, with their markers; the Steiner vertices
/// in the triangulation's order; the domain's faces (counter-clockwise, marker 0).
inline triangle_mesh extract(cdt& tr, const pslg& g) {
  triangle_mesh m;
  m.vertices = g.vertices;
  m.vertex_markers = g.vertex_markers;
  m.vertex_markers.resize(g.vertices.size(), 0);
  auto next = static_cast<index_t>(g.vertices.size());
  for (auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
    if (v->info().id != no_index) continue;
    v->info().id = next++;
    m.vertices.push_back({v->point().x(), v->point().y()});
    m.vertex_markers.push_back(0);
  }
  for (auto f = tr.finite_faces_begin(); f != tr.finite_faces_end(); ++f)
    if (f->is_in_domain())
      m.triangles.push_back(
          {f->vertex(0)->info().id, f->vertex(1)->info().id, f->vertex(2)->info().id});
  m.triangle_markers.assign(m.triangles.size(), 0);
  extract_segments(tr, g, m);
  return m;
}

} // namespace pdd::triangle::detail::conforming

namespace pdd::triangle::detail {

/// Meshes a PSLG for switch D or S (see conforming.hpp's file comment) on one triangulation:
/// without q or a, conforming Delaunay; with them, Delaunay refinement under q's angle, a's
/// area and `sizing` (the regional or previous-mesh bounds), every segment Gabriel when it ends;
/// at most sw.max_steiner points either way. Vertices as pdd::triangle::triangulate numbers
/// them; A's attributes per triangle. \throws pdd::geometry_error as pdd::validate.
/// Complexity O(n log n) expected in the output size; one thread.
inline triangulation conforming_mesh(pslg domain, const switches& sw, const any_sizing& sizing) {
  domain.rule = domain_rule::triangle;
  validate(domain);
  namespace cf = conforming;
  cf::cdt tr;
  cf::build(tr, domain);
  cf::mark_domain(tr, domain.holes);
  cf::release_outside_segments(tr, domain.holes);
  if (!sw.quality) {
    cf::make_conforming(tr, sw.max_steiner);
    cf::mark_domain(tr, domain.holes); // the conformer does not keep the marks of new faces
  } else {
    mesh_criteria c;
    c.min_angle_deg = sw.min_angle_deg;
    c.max_area = sw.max_area > 0.0 ? sw.max_area : std::numeric_limits<double>::infinity();
    cf::refine(tr, c, sizing, sw.max_steiner);
  }
  triangulation out;
  out.mesh = cf::extract(tr, domain);
  if (sw.regional_attributes) out.triangle_attributes = region_attributes(domain, out.mesh);
  return out;
}

} // namespace pdd::triangle::detail

#endif // PDD_PERMISSIVE
