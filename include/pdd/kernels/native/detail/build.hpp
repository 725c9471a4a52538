/// \file build.hpp
/// The constrained Delaunay triangulation of a pslg in the native triangulation: input vertices
/// inserted in Hilbert order (CGAL's spatial_sort) with walking point location, segments
/// recovered by flips (Sloan 1993: flip the edges crossing a segment until it appears), the
/// constrained Delaunay property restored by Lawson's flips, and the domain marked by flood fill
/// (pdd::flood_levels: odd nesting level, less the regions of hole points).
#pragma once

#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_measures.hpp>
#include <pdd/core/triangulation_levels.hpp>
#include <pdd/errors.hpp>
#include <pdd/kernels/detail/mesher_input.hpp>
#include <pdd/kernels/native/detail/insertion.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace pdd::detail::native_mesh {

/// Inserts the input vertices: vertex i of d is vertex i of tr; the bounding triangle's three
/// vertices follow them. \throws meshing_error for non-finite or coinciding vertices.
inline void insert_vertices(triangulation& tr, cavity& cav, const pslg& d) {
  const std::vector<std::size_t> order = spatial_insertion_order(d, no_index / 2 - 3).order;
  tr.pts = d.vertices;
  tr.start_bounding_triangle();
  std::uint32_t rng = 12345u, hint = 0;
  for (const std::size_t i : order) {
    const point& p = d.vertices[i];
    const std::uint32_t t = tr.locate(p, hint, rng);
    for (int k = 0; k < 3; ++k)
      if (tr.at(t, k).x == p.x && tr.at(t, k).y == p.y)
        throw meshing_error(-1, "vertices " + std::to_string(tr.corner(t)[k]) + " and " +
                                    std::to_string(i) + " coincide");
    cav.grow(tr, p, {t}, no_ref);
    cav.commit(tr, static_cast<index_t>(i));
    hint = cav.created().front();
  }
}

/// The edges crossed by segment s = (a, b) (no edge of tr), as (left, right) vertex pairs in
/// order from a. \throws meshing_error when an input vertex lies on the segment or a crossed
/// edge is constrained (two segments intersect).
inline void crossed_edges(const triangulation& tr, index_t a, index_t b, std::size_t s,
                          std::vector<std::pair<index_t, index_t>>& out) {
  out.clear();
  const point &pa = tr.pts[a], &pb = tr.pts[b];
  const std::string name = "segment " + std::to_string(s);
  std::uint32_t t = tr.vertex_tri[a];
  for (;;) { // rotate around a to the triangle the segment leaves a through
    const int k = tr.index_of(t, a);
    const point &q = tr.at(t, next3(k)), &r = tr.at(t, prev3(k));
    const int oq = orient(pa, pb, q);
    if (oq == 0 && (q.x - pa.x) * (pb.x - pa.x) + (q.y - pa.y) * (pb.y - pa.y) > 0)
      throw meshing_error(-1, name + " contains an input vertex");
    if (oq < 0 && orient(pa, pb, r) > 0) break;
    t = ref_tri(tr.adj(t)[prev3(k)]);
  }
  int edge = tr.index_of(t, a);
  index_t right = tr.corner(t)[next3(edge)], left = tr.corner(t)[prev3(edge)];
  for (;;) {
    if (tr.constrained(t, edge)) throw meshing_error(-1, name + " intersects another segment");
    out.emplace_back(left, right);
    const ref_t n = tr.adj(t)[edge];
    t = ref_tri(n);
    const index_t apex = tr.corner(t)[ref_edge(n)];
    if (apex == b) return;
    const int o = orient(pa, pb, tr.pts[apex]);
    if (o == 0) throw meshing_error(-1, name + " contains an input vertex");
    // The next crossed edge joins the apex to the vertex on the other side.
    edge = tr.index_of(t, o > 0 ? left : right);
    (o > 0 ? left : right) = apex;
  }
}

/// Makes segment (a, b) an edge by flipping the edges that cross it (Sloan 1993), and
/// constrains it. Each flip needs a strictly convex quadrilateral; an edge that cannot be
/// flipped yet goes to the back of the queue.
inline void recover_segment(triangulation& tr, index_t a, index_t b, std::size_t s,
                            std::vector<std::pair<index_t, index_t>>& queue) {
  ref_t r = tr.find_edge(a, b);
  if (r == no_ref) {
    crossed_edges(tr, a, b, s, queue);
    const point &pa = tr.pts[a], &pb = tr.pts[b];
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const ref_t e = tr.find_edge(queue[head].first, queue[head].second);
      const std::uint32_t t = ref_tri(e);
      const int i = ref_edge(e);
      const ref_t nb = tr.adj(t)[i];
      const index_t p = tr.corner(t)[i], sv = tr.corner(ref_tri(nb))[ref_edge(nb)];
      const point &pp = tr.pts[p], &ps = tr.pts[sv];
      if (orient(pp, tr.at(t, next3(i)), ps) <= 0 || orient(ps, tr.at(t, prev3(i)), pp) <= 0) {
        queue.push_back(queue[head]); // not convex yet
        continue;
      }
      tr.flip(t, i);
      if (p != a && p != b && sv != a && sv != b && orient(pa, pb, pp) * orient(pa, pb, ps) < 0)
        queue.emplace_back(p, sv);
    }
    r = tr.find_edge(a, b);
  }
  tr.constrain(ref_tri(r), ref_edge(r));
}

/// Lawson's flips until every unconstrained edge is locally Delaunay.
inline void make_delaunay(triangulation& tr) {
  std::vector<ref_t> stack;
  for (std::uint32_t t = 0; t < tr.size(); ++t)
    for (int i = 0; i < 3; ++i)
      if (tr.adj(t)[i] != no_ref && ref_tri(tr.adj(t)[i]) > t) stack.push_back(make_ref(t, i));
  while (!stack.empty()) {
    const std::uint32_t t = ref_tri(stack.back());
    const int i = ref_edge(stack.back());
    stack.pop_back();
    const ref_t nb = tr.adj(t)[i];
    if (nb == no_ref || tr.constrained(t, i)) continue;
    const std::uint32_t u = ref_tri(nb);
    if (!in_circle(tr.at(t, 0), tr.at(t, 1), tr.at(t, 2), tr.at(u, ref_edge(nb)))) continue;
    tr.flip(t, i);
    for (const ref_t e : {make_ref(t, 0), make_ref(t, 2), make_ref(u, 0), make_ref(u, 2)})
      stack.push_back(e);
  }
}

/// A face of the native triangulation seen as a CGAL face handle, for pdd::flood_levels.
struct face_ref {
  const triangulation* tr = nullptr;
  std::uint32_t t = no_ref;
  const face_ref* operator->() const noexcept { return this; }
  face_ref neighbor(int i) const noexcept {
    const ref_t n = tr->adj(t)[i];
    return {tr, n == no_ref ? t : ref_tri(n)};
  }
  bool is_constrained(int i) const noexcept { return tr->constrained(t, i); }
};
struct flood_view {
  using Face_handle = face_ref;
  const triangulation* tr;
  index_t outer_vertex;
  face_ref infinite_face() const noexcept { return {tr, tr->vertex_tri[outer_vertex]}; }
};

/// Marks the domain by d.rule: odd nesting level, or (Triangle's rule) level >= 1, less every
/// region reached from a hole point without crossing a segment.
inline void mark_domain(triangulation& tr, const pslg& d) {
  std::vector<int> level(tr.size(), -1);
  flood_levels(flood_view{&tr, static_cast<index_t>(d.vertices.size())},
               [&level](face_ref f) -> int& { return level[f.t]; });
  for (std::uint32_t t = 0; t < tr.size(); ++t)
    if (d.rule == domain_rule::odd_nesting ? level[t] % 2 == 1 : level[t] >= 1)
      tr.flags(t) = static_cast<std::uint8_t>(tr.flags(t) | in_domain_bit);
  std::vector<std::uint32_t> stack;
  std::uint32_t rng = 777u;
  for (const point& h : d.holes) {
    if (!std::isfinite(h.x) || !std::isfinite(h.y)) continue;
    const std::uint32_t t = tr.locate(h, 0, rng);
    if (!tr.in_domain(t)) continue;
    tr.flags(t) = static_cast<std::uint8_t>(tr.flags(t) & ~in_domain_bit);
    stack.assign(1, t);
    while (!stack.empty()) {
      const std::uint32_t f = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        const ref_t n = tr.adj(f)[i];
        if (n == no_ref || tr.constrained(f, i) || !tr.in_domain(ref_tri(n))) continue;
        tr.flags(ref_tri(n)) = static_cast<std::uint8_t>(tr.flags(ref_tri(n)) & ~in_domain_bit);
        stack.push_back(ref_tri(n));
      }
    }
  }
}

/// Reserves the arrays for the mesh an area bound of max_area makes of the marked domain (about
/// its area / (pdd::mean_triangle_area_fraction max_area) triangles, half as many vertices; at most
/// 2^26 triangles), so that they are not copied as they grow: growing by doubling copied them and
/// touched twice their final memory. A finer sizing field only makes them grow past the
/// reservation.
inline void reserve_for_area_bound(triangulation& tr, std::vector<index_t>& vertex_ids,
                                   double max_area) {
  if (!(max_area > 0) || !std::isfinite(max_area)) return;
  double area = 0;
  for (std::uint32_t t = 0; t < tr.size(); ++t)
    if (tr.in_domain(t)) area += triangle_area(tr.at(t, 0), tr.at(t, 1), tr.at(t, 2));
  const double triangles =
      std::min(1.05 * area / (mean_triangle_area_fraction * max_area), 67108864.0);
  const auto slots = tr.slots.size() + static_cast<std::size_t>(triangles);
  const auto vertices = tr.pts.size() + static_cast<std::size_t>(triangles / 2);
  tr.slots.reserve(slots);
  tr.pts.reserve(vertices);
  tr.vertex_tri.reserve(vertices);
  vertex_ids.reserve(vertices);
}

/// The constrained Delaunay triangulation of d with its domain marked.
/// \throws meshing_error for unusable input (see pdd::native::mesher).
inline void build(triangulation& tr, cavity& cav, const pslg& d) {
  insert_vertices(tr, cav, d);
  const std::size_t n = d.vertices.size();
  std::vector<std::pair<index_t, index_t>> queue;
  for (std::size_t s = 0; s < d.segments.size(); ++s) {
    const segment& sg = d.segments[s];
    const std::string name = "segment " + std::to_string(s);
    if (sg.a >= n || sg.b >= n) throw meshing_error(-1, name + " has a bad vertex index");
    if (sg.a == sg.b) throw meshing_error(-1, name + " has coinciding endpoints");
    recover_segment(tr, sg.a, sg.b, s, queue);
  }
  make_delaunay(tr);
  mark_domain(tr, d);
}

} // namespace pdd::detail::native_mesh
