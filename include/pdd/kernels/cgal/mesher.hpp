/// \file mesher.hpp
/// pdd::cgal::mesher: the default DelaunayMesher, over CGAL's constrained Delaunay
/// triangulation and Mesh_2 Delaunay refinement.
#pragma once

#include <pdd/concepts/delaunay_mesher.hpp>
#include <pdd/concepts/sizing_field.hpp>
#include <pdd/detail/cgal_mesher.hpp>
#include <pdd/errors.hpp>
#include <pdd/kernels/cgal/criteria.hpp>

#include <CGAL/exceptions.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <string>

namespace pdd::cgal {

/// Meshes one planar straight-line domain with CGAL 5.5's Constrained_Delaunay_triangulation_2
/// (Epick kernel) refined by the levels of Delaunay_mesher_2 (Ruppert-type refinement with
/// Shewchuk's cluster handling for small input angles), under a shape bound and an area bound
/// (criteria.max_area and a SizingField) — dissertation ch. 1.1 and 6.1, the sequential mesher
/// every subdomain is handed to. Models pdd::DelaunayMesher; see its semantics.
///
/// Differences from CGAL's Delaunay_mesher_2: the domain is marked before refinement (odd
/// nesting of segment loops, less hole regions, see concepts/delaunay_mesher.hpp), a segment
/// counts as encroached only by vertices on a side of it that lies in the domain (as in
/// Triangle), and the criteria are pdd::cgal::sizing_criteria.
///
/// Output: the input vertices first, in input order, with their coordinates and markers copied
/// bit for bit; then the Steiner vertices in the triangulation's insertion order (deterministic:
/// the same input gives bitwise the same output). A Steiner vertex on an input segment gets
/// the segment's marker, any other 0. Triangles are the in-domain faces, counter-clockwise,
/// marker 0; `segments` holds the mesh edges on input segments (sorted, a < b) with their
/// segment's marker.
///
/// Thread-safety: the object is stateless; any number of `mesh` calls may run concurrently.
struct mesher {
  /// Meshes the domain of d. Complexity: O(n log n) expected in the output size n.
  /// \tparam S a SizingField (area bound at a point, sampled at triangle centroids).
  /// \pre criteria.min_angle_deg in [0, 60) (refinement is guaranteed to terminate for
  ///   <= 20.7 deg with input angles >= 60 deg, and usually does up to about 33 deg);
  ///   criteria.max_area > 0; sizing.area_at > 0 everywhere.
  /// \throws meshing_error (subdomain -1) for unusable input (non-finite or coinciding
  ///   vertices, bad or crossing segments, a vertex inside a segment, marker count mismatch,
  ///   criteria out of range) or when CGAL fails.
  template <SizingField S>
  mesher_result mesh(const pslg& d, const mesh_criteria& criteria, const S& sizing) const {
    check(d, criteria);
    try {
      return run(d, criteria, sizing);
    } catch (const pdd::error&) {
      throw;
    } catch (const std::exception& e) {
      throw meshing_error(-1, std::string("CGAL failed: ") + e.what());
    }
  }

private:
  static void check(const pslg& d, const mesh_criteria& c) {
    if (!d.vertex_markers.empty() && d.vertex_markers.size() != d.vertices.size())
      throw meshing_error(-1, "vertex_markers has " + std::to_string(d.vertex_markers.size()) +
                                  " entries for " + std::to_string(d.vertices.size()) +
                                  " vertices");
    if (!(c.min_angle_deg >= 0.0 && c.min_angle_deg < 60.0))
      throw meshing_error(-1, "min_angle_deg must lie in [0, 60), got " +
                                  std::to_string(c.min_angle_deg));
    if (!(c.max_area > 0.0))
      throw meshing_error(-1, "max_area must be > 0, got " + std::to_string(c.max_area));
  }

  template <SizingField S>
  static mesher_result run(const pslg& d, const mesh_criteria& c, const S& sizing) {
    namespace dm = detail::cgal_mesh;
    dm::cdt tr;
    const std::vector<dm::vertex_handle> vh = dm::build_cdt(tr, d);
    if (tr.dimension() == 2) {
      dm::mark_domain(tr, d.holes);
      sizing_criteria<dm::cdt, S> crit(c.shape_bound(), c.max_area, sizing);
      dm::refine(tr, crit);
    }
    return extract(tr, d, vh);
  }

  static mesher_result extract(detail::cgal_mesh::cdt& tr, const pslg& d,
                               const std::vector<detail::cgal_mesh::vertex_handle>& vh) {
    namespace dm = detail::cgal_mesh;
    const dm::segment_table table(d);
    const auto marker_of = [&](index_t s) { return s == dm::none ? 0 : d.segments[s].marker; };
    mesher_result r;
    triangle_mesh& m = r.mesh;
    const std::size_t n = d.vertices.size();
    m.vertices.reserve(tr.number_of_vertices());
    m.vertex_markers.reserve(tr.number_of_vertices());
    m.vertices = d.vertices;
    m.vertex_markers = d.vertex_markers;
    m.vertex_markers.resize(n, 0);
    auto next = static_cast<index_t>(n);
    for (auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
      dm::vertex_info& info = v->info();
      if (info.id != dm::none) continue;
      info.id = next++;
      m.vertices.push_back({v->point().x(), v->point().y()});
      m.vertex_markers.push_back(
          info.seg_a == dm::none ? 0 : marker_of(table.find(info.seg_a, info.seg_b)));
    }
    if (tr.dimension() == 2) {
      m.triangles.reserve(tr.number_of_faces());
      for (auto f = tr.finite_faces_begin(); f != tr.finite_faces_end(); ++f)
        if (f->is_in_domain())
          m.triangles.push_back(
              {f->vertex(0)->info().id, f->vertex(1)->info().id, f->vertex(2)->info().id});
      m.triangle_markers.assign(m.triangles.size(), 0);
      for (auto e = tr.finite_edges_begin(); e != tr.finite_edges_end(); ++e) {
        const auto& [f, i] = *e;
        if (!f->is_constrained(i) || !(f->is_in_domain() || f->neighbor(i)->is_in_domain()))
          continue;
        const dm::vertex_info& a = f->vertex(dm::cdt::cw(i))->info();
        const dm::vertex_info& b = f->vertex(dm::cdt::ccw(i))->info();
        const index_t s = a.seg_a != dm::none   ? table.find(a.seg_a, a.seg_b)
                          : b.seg_a != dm::none ? table.find(b.seg_a, b.seg_b)
                                                : table.find(a.id, b.id);
        m.segments.push_back({std::min(a.id, b.id), std::max(a.id, b.id), marker_of(s)});
      }
      std::sort(m.segments.begin(), m.segments.end(), [](const mesh_edge& x, const mesh_edge& y) {
        return x.a != y.a ? x.a < y.a : x.b < y.b;
      });
    }
    // A split segment's two halves may meet at a rounded midpoint slightly off the line, so
    // its endpoints can still be joined by an (unconstrained) edge: test the constraint.
    for (std::size_t s = 0; s < d.segments.size(); ++s) {
      dm::face_handle f;
      int i = 0;
      if (!tr.is_edge(vh[d.segments[s].a], vh[d.segments[s].b], f, i) || !f->is_constrained(i))
        r.split_segments.push_back(static_cast<index_t>(s));
    }
    return r;
  }
};

} // namespace pdd::cgal

static_assert(pdd::DelaunayMesher<pdd::cgal::mesher>);
