/// \file triangulation.hpp
/// Implementation detail of MADD: the boundary discretisation Z of a region and its
/// boundary-conforming Delaunay triangulation (dissertation 3.2, conditions (i)-(ii), and the
/// static/dynamic refinement of 4.1).
///
/// Every region edge longer than the target length h is bisected (exact canonical midpoints)
/// to 2^d pieces of length <= h. Then every piece whose diametral circle contains a vertex of
/// Z (tested on the constrained Delaunay triangulation, exact predicates) is bisected until no
/// piece is encroached (condition (ii)): the CDT is then the Delaunay triangulation of Z and
/// every circumcentre lies in the region (Lemma 4). Small input angles can make this cascade
/// forever (two pieces at a corner of angle < 60 degrees encroach on each other at every
/// level), so a piece is bisected at most max_encroachment_depth times; the MADD steps after
/// this one never rely on condition (ii) for correctness, only for the number of junction
/// triangles.
#pragma once

#include <pdd/core/kernel.hpp>
#include <pdd/core/triangulation_levels.hpp>
#include <pdd/errors.hpp>
#include <pdd/madd/detail/region.hpp>
#include <pdd/triangulation/constrained_delaunay_2.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace pdd::detail {

/// One vertex of the discretisation Z of a region's boundary.
struct madd_zvertex {
  point p;
  int marker = 0;
  std::uint32_t loop = 0; ///< region loop
  std::uint32_t edge = 0; ///< region edge leaving this vertex (original) or containing it
  bool original = true;   ///< a vertex of the region (else a refinement vertex)
  std::uint8_t depth = 0; ///< encroachment bisections that created it
  double t = 0.0;         ///< refinement vertex: exact dyadic parameter on the edge, canonical
  std::uint32_t prev = 0; ///< previous vertex of Z along the loop
  std::uint32_t next = 0; ///< next vertex of Z along the loop
  point far_prev;         ///< region vertex that the boundary direction "backwards" points to
  point far_next;         ///< region vertex that the boundary direction "forwards" points to
};

/// One triangle of the triangulation of a region (inside the region only).
struct madd_face {
  std::array<std::uint32_t, 3> v{}; ///< vertices of Z, counter-clockwise
  /// Triangle across the edge opposite v[i]; -1 when that edge is a piece of the boundary.
  std::array<std::int32_t, 3> nb{};
};

/// Z and the triangles of its constrained Delaunay triangulation that lie in the region.
struct madd_triangulation {
  std::vector<madd_zvertex> z;
  std::vector<madd_face> faces;
  std::size_t encroachment_splits = 0;
};

/// The MADD triangulation (vertex info: the Z vertex; face info: the nesting level, then the
/// face's index in madd_triangulation::faces), built with constraint_crossing::
/// split_at_vertices.
using madd_cdt = constrained_delaunay_2<std::uint32_t, int>;

/// Parameter (canonical orientation of the region edge) of Z vertex w seen from the edge
/// that starts at or contains Z vertex u (w == u or w == z[u].next).
inline double z_edge_param(const madd_region& r, const madd_triangulation& tr, std::uint32_t u,
                           std::uint32_t w) {
  const madd_zvertex& zu = tr.z[u];
  const madd_zvertex& zw = tr.z[w];
  const madd_loop& l = r.loops[zu.loop];
  const point a = l.points[zu.edge];
  const point b = l.points[(zu.edge + 1) % l.size()];
  const bool a_lo = a < b;
  if (w == u) return zu.original ? (a_lo ? 0.0 : 1.0) : zu.t;
  return zw.original ? (a_lo ? 1.0 : 0.0) : zw.t;
}

/// Appends the 2^depth - 1 bisection points of region edge (loop l, edge e) in loop order.
inline void refine_region_edge(const madd_region& r, std::uint32_t l, std::uint32_t e, int depth,
                               std::vector<madd_zvertex>& z) {
  const madd_loop& lp = r.loops[l];
  const point a = lp.points[e];
  const point b = lp.points[(e + 1) % lp.size()];
  const bool a_lo = a < b;
  const point lo = a_lo ? a : b;
  const point hi = a_lo ? b : a;
  const int marker = lp.tags[e].external ? lp.tags[e].marker : 0;
  std::vector<std::pair<double, point>> pts;
  pts.reserve((std::size_t{1} << depth) - 1);
  // In-order traversal of the bisection tree (depth <= 30).
  auto rec = [&](auto&& self, point p, point q, double tp, double tq, int d) -> void {
    if (d == 0) return;
    const point m = canonical_midpoint(p, q);
    const double tm = 0.5 * (tp + tq);
    self(self, p, m, tp, tm, d - 1);
    pts.emplace_back(tm, m);
    self(self, m, q, tm, tq, d - 1);
  };
  rec(rec, lo, hi, 0.0, 1.0, depth);
  if (!a_lo) std::reverse(pts.begin(), pts.end());
  for (const auto& [t, p] : pts) {
    madd_zvertex v;
    v.p = p;
    v.marker = marker;
    v.loop = l;
    v.edge = e;
    v.original = false;
    v.t = t;
    v.far_prev = a;
    v.far_next = b;
    z.push_back(v);
  }
}

/// The bisection depth of an edge of length len at target length h: 2^depth pieces of length
/// <= h (at most 30).
inline int refinement_depth(double len, double h) noexcept {
  int depth = 0;
  while (depth < 30 && len > h * std::ldexp(1.0, depth))
    ++depth;
  return depth;
}

/// The most points Z may have: a region whose boundary would need more at the spacing asked
/// for (a sliver: its area, and so h, is tiny against its perimeter) is not split at that
/// spacing rather than exhausting memory.
inline constexpr double max_z_points = 4194304.0;

/// Why a split at spacing h is not tried: Z would exceed max_z_points.
inline std::string too_many_z_points(double h) {
  std::ostringstream s;
  s << "its boundary would need more than " << std::llround(max_z_points) << " points at spacing "
    << h << " (a sliver: tiny area for its perimeter)";
  return s.str();
}

/// |Z| that build_z(r, h) would make.
inline double z_point_count(const madd_region& r, double h) noexcept {
  double n = 0.0;
  for (const madd_loop& lp : r.loops)
    for (std::size_t e = 0; e < lp.size(); ++e)
      n += std::ldexp(1.0,
                      refinement_depth(distance(lp.points[e], lp.points[(e + 1) % lp.size()]), h));
  return n;
}

/// Static refinement (4.1): Z for a region, every region edge in 2^d pieces of length <= h,
/// linked along its loops.
inline void build_z(const madd_region& r, double h, std::vector<madd_zvertex>& z) {
  for (std::uint32_t l = 0; l < r.loops.size(); ++l) {
    const madd_loop& lp = r.loops[l];
    const auto first = static_cast<std::uint32_t>(z.size());
    for (std::uint32_t e = 0; e < lp.size(); ++e) {
      const point a = lp.points[e];
      const point b = lp.points[(e + 1) % lp.size()];
      madd_zvertex v;
      v.p = a;
      v.marker = lp.markers[e];
      v.loop = l;
      v.edge = e;
      v.original = true;
      v.far_prev = lp.points[(e + lp.size() - 1) % lp.size()];
      v.far_next = b;
      z.push_back(v);
      refine_region_edge(r, l, e, refinement_depth(distance(a, b), h), z);
    }
    const auto last = static_cast<std::uint32_t>(z.size());
    for (std::uint32_t i = first; i < last; ++i) {
      z[i].next = i + 1 == last ? first : i + 1;
      z[i].prev = i == first ? last - 1 : i - 1;
    }
  }
}

/// The constrained Delaunay triangulation of Z (every piece a constraint); handle[i] is the
/// vertex of Z vertex i. Z vertices at one point (a pinch vertex, visited once per sector of
/// the region there) share one vertex, whose info is one of them: twin[i] is the next Z vertex
/// at z[i]'s point, cyclically (i when it is alone).
inline void insert_z(const std::vector<madd_zvertex>& z, madd_cdt& cdt,
                     std::vector<madd_cdt::Vertex_handle>& handle,
                     std::vector<std::uint32_t>& twin) {
  std::vector<std::pair<epick::Point_2, std::uint32_t>> pts;
  pts.reserve(z.size());
  for (std::uint32_t i = 0; i < z.size(); ++i)
    pts.emplace_back(epick::Point_2(z[i].p.x, z[i].p.y), i);
  cdt.insert(pts.begin(), pts.end());
  handle.assign(z.size(), madd_cdt::Vertex_handle());
  twin.resize(z.size());
  for (std::uint32_t i = 0; i < z.size(); ++i)
    twin[i] = i;
  for (auto v : cdt.finite_vertex_handles())
    handle[v->info()] = v;
  for (std::uint32_t i = 0; i < z.size(); ++i)
    if (handle[i] == madd_cdt::Vertex_handle()) { // a second visit: the vertex is there
      const auto before = cdt.number_of_vertices();
      handle[i] = cdt.insert(pts[i].first);
      PDD_ASSERT(cdt.number_of_vertices() == before);
      const std::uint32_t r = handle[i]->info();
      twin[i] = twin[r];
      twin[r] = i;
    }
  for (std::uint32_t i = 0; i < z.size(); ++i)
    cdt.insert_constraint(handle[i], handle[z[i].next]);
}

/// The Z vertex at vertex k of face f that belongs to the sector of the region containing f
/// (twin: see insert_z): turning clockwise around it from f to the first piece of Z, that
/// piece is the one leaving the visit (the region lies counter-clockwise from it).
inline std::uint32_t visit_of_face(const std::vector<madd_zvertex>& z,
                                   const std::vector<madd_cdt::Vertex_handle>& handle,
                                   const std::vector<std::uint32_t>& twin, madd_cdt::Face_handle f,
                                   int k) {
  const auto vh = f->vertex(k);
  const std::uint32_t first = vh->info();
  if (twin[first] == first) return first;
  int i = k;
  while (!f->is_constrained(madd_cdt::cw(i))) {
    f = f->neighbor(madd_cdt::cw(i));
    i = f->index(vh);
  }
  const auto leaving = f->vertex(madd_cdt::ccw(i));
  std::uint32_t o = first;
  while (handle[z[o].next] != leaving) {
    o = twin[o];
    PDD_ASSERT(o != first);
  }
  return o;
}

/// Whether the piece (f, fi) has a vertex of the triangulation strictly inside its diametral
/// circle: the apex of one of its two triangles (exact predicate).
inline bool piece_encroached(const madd_cdt& cdt, madd_cdt::Face_handle f, int fi) {
  const auto pu = f->vertex(madd_cdt::ccw(fi))->point(), pw = f->vertex(madd_cdt::cw(fi))->point();
  for (int side = 0; side < 2; ++side) {
    const auto g = side == 0 ? f : f->neighbor(fi);
    const int gi = side == 0 ? fi : g->index(f);
    const auto apex = g->vertex(gi);
    if (cdt.is_infinite(apex)) continue;
    if (CGAL::side_of_bounded_circle(pu, pw, apex->point()) == CGAL::ON_BOUNDED_SIDE) return true;
  }
  return false;
}

/// The midpoint vertex that bisects piece u -> w (Z vertices; canonical midpoint), not yet
/// linked into Z.
inline madd_zvertex piece_midpoint(const madd_region& r, const madd_triangulation& tr,
                                   std::uint32_t u, std::uint32_t w) {
  const auto& z = tr.z;
  madd_zvertex m;
  m.p = canonical_midpoint(z[u].p, z[w].p);
  m.loop = z[u].loop;
  m.edge = z[u].edge;
  m.original = false;
  m.depth = static_cast<std::uint8_t>(std::max(z[u].depth, z[w].depth) + 1);
  m.t = 0.5 * (z_edge_param(r, tr, u, u) + z_edge_param(r, tr, u, w));
  const madd_loop& lp = r.loops[m.loop];
  m.marker = lp.tags[m.edge].external ? lp.tags[m.edge].marker : 0;
  m.far_prev = lp.points[m.edge];
  m.far_next = lp.points[(m.edge + 1) % lp.size()];
  m.prev = u;
  m.next = w;
  return m;
}

/// The pieces of Z that are constrained edges around vertex vh, queued for a check (twin:
/// see insert_z).
inline void queue_pieces_around(const madd_cdt& cdt, const std::vector<madd_zvertex>& z,
                                const std::vector<std::uint32_t>& twin, madd_cdt::Vertex_handle vh,
                                std::deque<std::uint32_t>& queue) {
  const auto queue_piece = [&](std::uint32_t x, std::uint32_t y) {
    std::uint32_t xo = x;
    do {
      std::uint32_t yo = y;
      do {
        if (z[xo].next == yo) return queue.push_back(xo);
        yo = twin[yo];
      } while (yo != y);
      xo = twin[xo];
    } while (xo != x);
  };
  auto fc = cdt.incident_faces(vh), done = fc;
  do {
    const int i = fc->index(vh);
    if (fc->is_constrained(i)) {
      const std::uint32_t x = fc->vertex(madd_cdt::ccw(i))->info();
      const std::uint32_t y = fc->vertex(madd_cdt::cw(i))->info();
      queue_piece(x, y);
      queue_piece(y, x);
    }
  } while (++fc != done);
}

/// Condition (ii) of 3.2: bisects encroached pieces until none is, or a piece has been
/// bisected max_depth times (small input angles cascade), or cannot be (a few ulps long).
inline void split_encroached_pieces(const madd_region& r, madd_triangulation& tr, madd_cdt& cdt,
                                    std::vector<madd_cdt::Vertex_handle>& handle,
                                    std::vector<std::uint32_t>& twin, int max_depth) {
  auto& z = tr.z;
  std::deque<std::uint32_t> queue;
  for (std::uint32_t i = 0; i < z.size(); ++i)
    queue.push_back(i);
  while (!queue.empty()) {
    const std::uint32_t u = queue.front();
    queue.pop_front();
    const std::uint32_t w = z[u].next;
    madd_cdt::Face_handle f;
    int fi = 0;
    if (!cdt.is_edge(handle[u], handle[w], f, fi)) continue; // already split
    if (std::max(z[u].depth, z[w].depth) >= max_depth) continue;
    if (!piece_encroached(cdt, f, fi)) continue;
    const madd_zvertex m = piece_midpoint(r, tr, u, w);
    if (m.p == z[u].p || m.p == z[w].p) continue; // a piece of a few ulps: cannot bisect
    const auto k = static_cast<std::uint32_t>(z.size());
    z.push_back(m);
    z[u].next = k;
    z[w].prev = k;
    cdt.remove_constrained_edge(f, fi);
    const auto before = cdt.number_of_vertices();
    const auto vh = cdt.insert(epick::Point_2(m.p.x, m.p.y), handle[u]->face());
    PDD_ASSERT(cdt.number_of_vertices() == before + 1); // a new vertex, not an old one
    vh->info() = k;
    handle.push_back(vh);
    twin.push_back(k);
    cdt.insert_constraint(handle[u], vh);
    cdt.insert_constraint(vh, handle[w]);
    ++tr.encroachment_splits;
    queue.push_back(u);
    queue.push_back(k);
    queue_pieces_around(cdt, z, twin, vh, queue);
  }
}

/// The faces inside the region (odd nesting level, pdd::flood_levels) as tr.faces, with
/// their neighbours across non-boundary edges; a vertex visited twice is the visit of the
/// face's sector (visit_of_face).
inline void collect_region_faces(madd_cdt& cdt, madd_triangulation& tr,
                                 const std::vector<madd_cdt::Vertex_handle>& handle,
                                 const std::vector<std::uint32_t>& twin) {
  for (auto f : cdt.all_face_handles())
    f->info() = -1;
  flood_levels(cdt, [](madd_cdt::Face_handle f) -> int& { return f->info(); });
  std::vector<madd_cdt::Face_handle> inside;
  for (auto f : cdt.finite_face_handles())
    if (f->info() % 2 == 1) inside.push_back(f);
  for (auto f : cdt.all_face_handles())
    f->info() = -1;
  for (std::size_t i = 0; i < inside.size(); ++i)
    inside[i]->info() = static_cast<int>(i);
  tr.faces.resize(inside.size());
  for (std::size_t i = 0; i < inside.size(); ++i) {
    const auto f = inside[i];
    madd_face& mf = tr.faces[i];
    for (int k = 0; k < 3; ++k) {
      mf.v[k] = visit_of_face(tr.z, handle, twin, f, k);
      mf.nb[k] = f->is_constrained(k) ? -1 : f->neighbor(k)->info();
      PDD_ASSERT(f->is_constrained(k) || mf.nb[k] >= 0);
    }
    for (int k = 0; k < 3; ++k)
      if (mf.nb[k] < 0) PDD_ASSERT(tr.z[mf.v[(k + 1) % 3]].next == mf.v[(k + 2) % 3]);
  }
}

/// Builds Z for a region (target piece length h > 0) and its constrained Delaunay
/// triangulation, bisecting encroached pieces at most max_encroachment_depth times each.
/// \pre r is a valid region: weakly simple loops (a loop may visit a pinch vertex once per
/// sector of the region there, and loops may touch there), holes inside the outer loop.
/// Complexity O(n log n) expected, n = |Z|. Thread-safe (no shared state).
inline madd_triangulation triangulate_region(const madd_region& r, double h,
                                             int max_encroachment_depth) {
  madd_triangulation tr;
  build_z(r, h, tr.z);
  madd_cdt cdt(constraint_crossing::split_at_vertices);
  std::vector<madd_cdt::Vertex_handle> handle;
  std::vector<std::uint32_t> twin;
  insert_z(tr.z, cdt, handle, twin);
  split_encroached_pieces(r, tr, cdt, handle, twin, max_encroachment_depth);
  collect_region_faces(cdt, tr, handle, twin);
  return tr;
}

} // namespace pdd::detail
