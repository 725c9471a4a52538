/// \file mesher.hpp
/// Implementation of pdd::cgal::mesher: the triangulation types, domain marking, the
/// refinement levels (CGAL Mesh_2's, with segment encroachment seen from the domain only) and
/// the extraction of the result.
#pragma once

#include <pdd/concepts/delaunay_mesher.hpp>
#include <pdd/core/kernel.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/core/triangulation_levels.hpp>
#include <pdd/errors.hpp>
#include <pdd/kernels/cgal/detail/cluster_rule.hpp>
#include <pdd/kernels/cgal/detail/domain_gabriel.hpp>
#include <pdd/kernels/cgal/detail/mesher_faces.hpp>
#include <pdd/kernels/detail/mesher_input.hpp>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Mesh_2/Clusters.h>
#include <CGAL/Mesh_2/Refine_edges.h>
#include <CGAL/Mesh_2/Refine_edges_visitor.h>
#include <CGAL/Mesh_2/Refine_edges_with_clusters.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cstdint>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace pdd::detail::cgal_mesh {

using vertex_base = CGAL::Triangulation_vertex_base_with_info_2<vertex_info, epick>;
/// The face info is the nesting level used while marking the domain.
using face_base =
    CGAL::Triangulation_face_base_with_info_2<int, epick, CGAL::Delaunay_mesh_face_base_2<epick>>;
using tds = CGAL::Triangulation_data_structure_2<vertex_base, face_base>;
/// No constraint may intersect another (CGAL throws), so no vertex is ever constructed.
using cdt =
    CGAL::Constrained_Delaunay_triangulation_2<epick, tds, CGAL::No_constraint_intersection_tag>;
using vertex_handle = cdt::Vertex_handle;
using face_handle = cdt::Face_handle;
using cgal_point = epick::Point_2;

/// CGAL's edge level with clusters, using domain_gabriel, with the cluster rule restricted to
/// clusters that meet the domain (domain_cluster_edges_base). After a segment split it restores
/// the domain marks of the new faces before the encroachment tests (CGAL restores them only
/// afterwards, in its visitor, which is harmless for its two-sided test but not for ours), and
/// records on the new vertex the input segment it lies on.
template <class Tr>
class domain_edges_base : public domain_cluster_edges_base<Tr, domain_gabriel<Tr>> {
  using super = domain_cluster_edges_base<Tr, domain_gabriel<Tr>>;
  using Vertex_handle = typename Tr::Vertex_handle;
  using Face_handle = typename Tr::Face_handle;

public:
  domain_edges_base(Tr& t, CGAL::Mesh_2::Clusters<Tr>& c) : super(t, c) {}

  /// Uses the lens rule on the subsegments it applies to (null: the disk alone).
  void set_lens_rule(const lens_rule* rule) { this->is_locally_conform.lens = rule; }
  /// The lens rule set by set_lens_rule (null: the disk alone).
  const lens_rule* lens_rule_in_use() const { return this->is_locally_conform.lens; }

  /// CGAL's conflict zone of the split point p of a constrained edge, after checking what
  /// CGAL only asserts in debug builds: one of the edge's two faces conflicts with p (its
  /// circumcircle holds p), and when the first does not, p lies in the second. With two
  /// constraints at a tiny angle (a fraction of a degree) the rounded split point of one can
  /// fall beyond the other, and the zone would corrupt the triangulation.
  /// \throws unresolvable_input_error naming the segment's endpoints.
  template <class Edge>
  auto conflicts_zone_impl(const typename Tr::Point& p, Edge edge) {
    typename Tr::Locate_type type{};
    int li = 0;
    const Face_handle at = this->tr.locate(p, type, li, edge.first);
    const Face_handle f = edge.first, n = f->neighbor(edge.second);
    const bool on_edge = type == Tr::EDGE;
    const bool f_conflicts = on_edge || this->tr.test_conflict(p, f);
    const bool n_conflicts = on_edge || this->tr.test_conflict(p, n);
    if ((!f_conflicts && n != at) || !(f_conflicts || n_conflicts)) {
      std::ostringstream what;
      what.precision(17);
      what << "the segment from " << f->vertex(Tr::cw(edge.second))->point() << " to "
           << f->vertex(Tr::ccw(edge.second))->point()
           << " cannot be split: its rounded split point falls beyond a neighbouring segment (an "
              "input angle too small to resolve in double precision)";
      throw unresolvable_input_error(-1, what.str());
    }
    return super::conflicts_zone_impl(p, edge);
  }

  void after_insertion_impl(const Vertex_handle& v) {
    restore_marks(v);
    const vertex_info& a = this->visitor_va->info();
    const vertex_info& b = this->visitor_vb->info();
    vertex_info& vi = v->info();
    if (a.seg_a != none) {
      vi.seg_a = a.seg_a;
      vi.seg_b = a.seg_b;
    } else if (b.seg_a != none) {
      vi.seg_a = b.seg_a;
      vi.seg_b = b.seg_b;
    } else {
      vi.seg_a = a.id;
      vi.seg_b = b.id;
    }
    super::after_insertion_impl(v);
  }

private:
  // Same walk as CGAL::Mesh_2::Refine_edges_visitor::after_insertion.
  void restore_marks(const Vertex_handle& v) {
    Tr& t = this->tr;
    Face_handle fh;
    int i = 0;
    t.is_edge(this->visitor_va, v, fh, i);
    auto fc = t.incident_faces(v, fh);
    const auto begin = fc;
    do {
      if (!t.is_infinite(fc)) fc->set_in_domain(this->visitor_mark_at_right);
      ++fc;
    } while (fc->vertex(Tr::ccw(fc->index(v))) != this->visitor_vb);
    do {
      if (!t.is_infinite(fc)) fc->set_in_domain(this->visitor_mark_at_left);
      ++fc;
    } while (fc != begin);
  }
};

/// Sets every face's nesting level (face info): the number of constrained edges crossed from
/// the infinite face (pdd::flood_levels, as CGAL's mark_domain_in_triangulation).
inline void mark_nesting(cdt& tr) {
  for (auto f = tr.all_faces_begin(); f != tr.all_faces_end(); ++f)
    f->info() = -1;
  flood_levels(tr, [](face_handle f) -> int& { return f->info(); });
}

/// Marks the domain by `rule` (pdd::domain_rule): odd_nesting, faces enclosed by an odd number
/// of constrained loops (odd nesting level); triangle, faces not reachable from the infinite
/// face without crossing a constraint (level >= 1); either less the constraint-bounded regions
/// that contain a hole point. Complexity O(faces + holes * locate).
inline void mark_domain(cdt& tr, const std::vector<point>& holes, domain_rule rule) {
  mark_nesting(tr);
  const bool odd = rule == domain_rule::odd_nesting;
  for (auto f = tr.all_faces_begin(); f != tr.all_faces_end(); ++f)
    f->set_in_domain(!tr.is_infinite(f) && (odd ? f->info() % 2 == 1 : f->info() >= 1));
  std::vector<face_handle> stack;
  for (const point& h : holes) {
    const face_handle f = tr.locate(cgal_point(h.x, h.y));
    if (f == face_handle() || tr.is_infinite(f) || !f->is_in_domain()) continue;
    f->set_in_domain(false);
    stack.push_back(f);
    while (!stack.empty()) {
      const face_handle g = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        const face_handle n = g->neighbor(i);
        if (!g->is_constrained(i) && n->is_in_domain()) {
          n->set_in_domain(false);
          stack.push_back(n);
        }
      }
    }
  }
}

/// Leaves out of the refinement, by Triangle's rule, every segment with no domain face on
/// either side (dangling in the unbounded face or in a hole): Triangle leaves it out of the
/// mesh, and so does extract(). Kept as a constraint it stalled refinement: domain_gabriel never
/// finds such a segment encroached (it counts vertices on domain sides only), so it is never
/// split, and a cluster it belongs to (an angle below 60 deg with a domain segment at a shared
/// vertex) is never reduced, so the bad faces inside the domain's small angle beside it were
/// refined without end (a fuzz finding: a 16.7 deg domain corner with a dangling segment outside
/// it ran out of memory). Its edges are un-constrained (CGAL restores the Delaunay property by
/// flips, all among faces outside the domain, which constraints separate from the domain's) and
/// the domain is marked again: the domain's faces are the same, since a path from the
/// unbounded face into the domain never crosses only such a segment.
/// \returns the number of segments left out. Complexity O(edges + faces).
inline std::size_t release_outside_segments(cdt& tr, const std::vector<point>& holes) {
  std::vector<std::pair<vertex_handle, vertex_handle>> outside;
  for (auto e = tr.finite_edges_begin(); e != tr.finite_edges_end(); ++e) {
    const face_handle f = e->first;
    const int i = e->second;
    const face_handle n = f->neighbor(i);
    if (f->is_constrained(i) && !(!tr.is_infinite(f) && f->is_in_domain()) &&
        !(!tr.is_infinite(n) && n->is_in_domain()))
      outside.emplace_back(f->vertex(cdt::cw(i)), f->vertex(cdt::ccw(i)));
  }
  for (const auto& [a, b] : outside) {
    face_handle f;
    int i = 0;
    if (tr.is_edge(a, b, f, i)) tr.remove_constrained_edge(f, i);
  }
  if (!outside.empty()) mark_domain(tr, holes, domain_rule::triangle);
  return outside.size();
}

/// Inserts the vertices, spatially sorted, with their input index as info.
/// \throws meshing_error for a non-finite coordinate or coinciding vertices.
/// \returns the vertex handle of every input vertex.
inline std::vector<vertex_handle> insert_vertices(cdt& tr, const pslg& d) {
  const spatial_insertion in = spatial_insertion_order(d, none);
  const std::vector<cgal_point>& pts = in.points;
  const std::vector<std::size_t>& order = in.order;
  const std::size_t n = pts.size();
  std::vector<vertex_handle> vh(n);
  face_handle hint;
  for (const std::size_t i : order) {
    const vertex_handle v = tr.insert(pts[i], hint);
    if (v->info().id != none)
      throw meshing_error(-1, "vertices " + std::to_string(v->info().id) + " and " +
                                  std::to_string(i) + " coincide");
    v->info().id = static_cast<index_t>(i);
    vh[i] = v;
    hint = v->face();
  }
  return vh;
}

/// Inserts the vertices and the segments (a repeated segment is inserted once).
/// \throws meshing_error for non-finite coordinates, coinciding vertices, bad segment indices,
/// degenerate segments, crossing segments or a vertex inside a segment.
/// \returns the vertex handle of every input vertex.
inline std::vector<vertex_handle> build_cdt(cdt& tr, const pslg& d) {
  const std::vector<vertex_handle> vh = insert_vertices(tr, d);
  const std::size_t n = d.vertices.size();
  for (std::size_t s = 0; s < d.segments.size(); ++s) {
    const segment& sg = d.segments[s];
    const std::string name = "segment " + std::to_string(s);
    if (sg.a >= n || sg.b >= n) throw meshing_error(-1, name + " has a bad vertex index");
    if (sg.a == sg.b) throw meshing_error(-1, name + " has coinciding endpoints");
    face_handle f;
    int i = 0;
    if (tr.is_edge(vh[sg.a], vh[sg.b], f, i) && f->is_constrained(i)) continue; // repeated
    try {
      tr.insert_constraint(vh[sg.a], vh[sg.b]);
    } catch (const cdt::Intersection_of_constraints_exception&) {
      throw meshing_error(-1, name + " intersects another segment");
    }
  }
  for (std::size_t s = 0; s < d.segments.size(); ++s) {
    const segment& sg = d.segments[s];
    if (!tr.is_edge(vh[sg.a], vh[sg.b]))
      throw meshing_error(-1, "segment " + std::to_string(s) + " contains an input vertex");
  }
  return vh;
}

/// CGAL's Delaunay_mesher_2 assembled from its levels, with domain_edges_base as the edge
/// level and faces_level (a heap-based bad-face queue) as the face level, started on a
/// triangulation whose in_domain marks are already set.
template <class Criteria>
void refine(cdt& tr, Criteria& criteria, const lens_rule* lens) {
  using edges_level =
      CGAL::Mesh_2::Refine_edges_with_clusters<cdt, domain_gabriel<cdt>, domain_edges_base<cdt>>;
  using faces = faces_level<cdt, Criteria, edges_level>;
  CGAL::Null_mesher_level null_level;
  CGAL::Null_mesh_visitor null_visitor;
  CGAL::Mesh_2::Clusters<cdt> clusters(tr);
  edges_level edges(tr, clusters, null_level);
  edges.set_lens_rule(lens);
  faces face_level(tr, criteria, edges);
  CGAL::Mesh_2::Refine_edges_visitor_from_faces<faces> visitor(face_level, edges, null_visitor);
  clusters.create_clusters();
  edges.scan_triangulation();
  face_level.scan_triangulation();
  face_level.refine(visitor);
}

/// Numbers the Steiner vertices after the input vertices, in the triangulation's (insertion)
/// order, and copies all vertices with their markers into m.
inline void extract_vertices(cdt& tr, const pslg& d, const segment_table& table, triangle_mesh& m) {
  const std::size_t n = d.vertices.size();
  m.vertices.reserve(tr.number_of_vertices());
  m.vertex_markers.reserve(tr.number_of_vertices());
  m.vertices.assign(d.vertices.begin(), d.vertices.end());
  m.vertex_markers.assign(d.vertex_markers.begin(), d.vertex_markers.end());
  m.vertex_markers.resize(n, 0);
  auto next = static_cast<index_t>(n);
  for (auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
    vertex_info& info = v->info();
    if (info.id != none) continue;
    info.id = next++;
    m.vertices.push_back({v->point().x(), v->point().y()});
    const index_t s = info.seg_a == none ? none : table.find(info.seg_a, info.seg_b);
    m.vertex_markers.push_back(s == none ? 0 : d.segments[s].marker);
  }
}

/// Copies the in-domain faces (counter-clockwise, marker 0) and the constrained edges that
/// bound or cross the domain (sorted, a < b, with their segment's marker) into m.
inline void extract_faces_and_segments(cdt& tr, const pslg& d, const segment_table& table,
                                       triangle_mesh& m) {
  m.triangles.reserve(tr.number_of_faces());
  for (auto f = tr.finite_faces_begin(); f != tr.finite_faces_end(); ++f)
    if (f->is_in_domain())
      m.triangles.push_back(
          {f->vertex(0)->info().id, f->vertex(1)->info().id, f->vertex(2)->info().id});
  m.triangle_markers.assign(m.triangles.size(), 0);
  for (auto e = tr.finite_edges_begin(); e != tr.finite_edges_end(); ++e) {
    const auto& [f, i] = *e;
    if (!f->is_constrained(i) || !(f->is_in_domain() || f->neighbor(i)->is_in_domain())) continue;
    const vertex_info& a = f->vertex(cdt::cw(i))->info();
    const vertex_info& b = f->vertex(cdt::ccw(i))->info();
    const index_t s = a.seg_a != none   ? table.find(a.seg_a, a.seg_b)
                      : b.seg_a != none ? table.find(b.seg_a, b.seg_b)
                                        : table.find(a.id, b.id);
    m.segments.push_back(
        {std::min(a.id, b.id), std::max(a.id, b.id), s == none ? 0 : d.segments[s].marker});
  }
  std::sort(m.segments.begin(), m.segments.end(), [](const mesh_edge& x, const mesh_edge& y) {
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
}

/// The result of a refined triangulation. A split segment's halves may meet at a rounded
/// midpoint slightly off the segment's line, so its endpoints can still be joined by an
/// (unconstrained) edge: a segment counts as unsplit only if it is a constrained edge.
inline mesher_result extract(cdt& tr, const pslg& d, const std::vector<vertex_handle>& vh) {
  const segment_table table(d);
  mesher_result r;
  extract_vertices(tr, d, table, r.mesh);
  if (tr.dimension() == 2) extract_faces_and_segments(tr, d, table, r.mesh);
  for (std::size_t s = 0; s < d.segments.size(); ++s) {
    face_handle f;
    int i = 0;
    if (!tr.is_edge(vh[d.segments[s].a], vh[d.segments[s].b], f, i) || !f->is_constrained(i))
      r.split_segments.push_back(static_cast<index_t>(s));
  }
  return r;
}

} // namespace pdd::detail::cgal_mesh
