/// \file domain_faces.hpp
/// pdd::domain_faces: the faces of a PSLG domain (by its rule: the pieces of the plane between
/// its segments that are in the domain) on its constrained Delaunay triangulation: the
/// triangles inside the domain with the face each lies in, and the face holding a point.
#pragma once

#include <pdd/core/index.hpp>
#include <pdd/core/point.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/geometry/detail/pslg_faces.hpp>
#include <pdd/geometry/loops.hpp>
#include <pdd/geometry/validate.hpp>

#include <array>
#include <vector>

namespace pdd {

/// A triangle of the domain's constrained Delaunay triangulation: PSLG vertex ids (ccw) and
/// the face it lies in (a dense id of the arrangement's faces, the same for every triangle of
/// one face; deterministic for a given PSLG).
struct domain_triangle {
  /// The triangle's PSLG vertex ids, counter-clockwise.
  std::array<index_t, 3> vertices;
  /// The face of the arrangement the triangle lies in (dense ids from 0, deterministic).
  index_t face;
};

/// Where a point lies relative to the domain's faces.
struct face_location {
  /// \enum kind
  /// inside a face of the domain, on its boundary (a segment or vertex), or outside it (in a
  /// hole or outside every loop).
  /// \var where
  /// Where the point lies; outside by default.
  enum class kind { inside, on_boundary, outside } where = kind::outside;
  index_t face = no_index; ///< the face (as domain_triangle::face) when where == inside
};

/// The faces of a PSLG domain by g.rule (pdd::domain_rule): odd_nesting labels them by the same
/// nesting flood fill as pdd::find_loops (hole points are not looked at), triangle by
/// Triangle's rule (detail::find_faces_into). One constrained Delaunay triangulation, CGAL,
/// exact predicates. Thread-safety: const member functions may be called concurrently.
class domain_faces {
public:
  /// \throws pdd::geometry_error as pdd::find_loops (odd_nesting) or pdd::validate (triangle).
  /// Complexity O(n log n) expected.
  explicit domain_faces(const pslg& g) { detail::faces_by_rule(g, pf_); }

  /// Tag of the validating constructor.
  struct validate_first {};

  /// Validates g (pdd::validate, default options) and keeps the faces validation found: those
  /// of Triangle's rule, whatever g.rule says (for a domain of closed loops, closed_loops(), the
  /// same domain as odd nesting). One constrained triangulation where validate() followed by
  /// domain_faces would build two. \throws pdd::geometry_error as pdd::validate.
  /// Complexity as pdd::validate.
  domain_faces(const pslg& g, validate_first) {
    detail::validate_into(g, validate_options{}, &pf_);
  }

  /// The triangles inside the domain (odd nesting level), in the triangulation's order
  /// (deterministic for a given PSLG). Complexity O(n).
  std::vector<domain_triangle> triangles() const {
    std::vector<domain_triangle> out;
    const detail::pslg_cdt& cdt = pf_.lt.triangulation.cdt;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
      if (pf_.in_domain(f))
        out.push_back(
            {{f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()}, f->info().face});
    return out;
  }

  /// The face holding p: on_boundary when p lies on a PSLG vertex or segment, outside when
  /// it lies in a hole or outside every loop. Complexity O(sqrt n) expected (CGAL's walk).
  face_location locate(const point& p) const {
    const detail::pslg_cdt& cdt = pf_.lt.triangulation.cdt;
    detail::pslg_cdt::Locate_type type{};
    int li = 0;
    const detail::pslg_cdt::Face_handle f = cdt.locate(detail::to_cgal(p), type, li);
    if (type == detail::pslg_cdt::VERTEX ||
        (type == detail::pslg_cdt::EDGE && f->is_constrained(li)))
      return {face_location::kind::on_boundary, no_index};
    if (type == detail::pslg_cdt::OUTSIDE_AFFINE_HULL ||
        type == detail::pslg_cdt::OUTSIDE_CONVEX_HULL || cdt.is_infinite(f) || !pf_.in_domain(f))
      return {face_location::kind::outside, no_index};
    return {face_location::kind::inside, f->info().face};
  }

  /// True when a triangle of the domain has PSLG vertex v as a corner (for an isolated
  /// vertex: it lies inside a face of the domain). Complexity O(degree of v).
  bool touches_domain(index_t v) const {
    const detail::pslg_cdt& cdt = pf_.lt.triangulation.cdt;
    auto fc = cdt.incident_faces(pf_.lt.triangulation.vertex[v]);
    const auto first = fc;
    do {
      if (!cdt.is_infinite(fc) && pf_.in_domain(fc)) return true;
    } while (++fc != first);
    return false;
  }

  /// True when a triangle of the domain lies on either side of the PSLG segment (a, b): false
  /// for a segment with no domain face on either side (by Triangle's rule a dangling segment in
  /// the unbounded face or in a hole, which is left out of the mesh). True as well when (a, b)
  /// is no edge of the triangulation (not a segment of the PSLG). Complexity O(degree of a).
  bool touches_domain(index_t a, index_t b) const {
    const detail::pslg_cdt& cdt = pf_.lt.triangulation.cdt;
    detail::pslg_cdt::Face_handle f;
    int i = 0;
    if (!cdt.is_edge(pf_.lt.triangulation.vertex[a], pf_.lt.triangulation.vertex[b], f, i))
      return true;
    const detail::pslg_cdt::Face_handle n = f->neighbor(i);
    return (!cdt.is_infinite(f) && pf_.in_domain(f)) || (!cdt.is_infinite(n) && pf_.in_domain(n));
  }

  /// The number of faces of the arrangement (domain_triangle::face < face_count()).
  std::size_t face_count() const noexcept { return pf_.face_in_domain.size(); }
  /// True when the domain is one of closed loops (see detail::pslg_faces::closed_loops).
  bool closed_loops() const noexcept { return pf_.closed_loops; }

  /// The loops of a domain of closed loops (as pdd::find_loops), else nullptr.
  const loop_structure* loops() const noexcept {
    return pf_.closed_loops ? &pf_.lt.structure : nullptr;
  }

  /// The area of the domain, bitwise as pdd::domain_area for Triangle's rule: the loops' areas
  /// for a domain of closed loops, else the sum of the face triangles' areas. Complexity O(n).
  double area() const {
    return pf_.closed_loops ? domain_area(pf_.lt.structure) : detail::faces_area(pf_);
  }

private:
  detail::pslg_faces pf_;
};

} // namespace pdd
