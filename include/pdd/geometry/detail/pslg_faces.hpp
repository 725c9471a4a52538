/// \file pslg_faces.hpp
/// The faces of a general PSLG's arrangement (Triangle's rule): the connected pieces of its
/// constrained Delaunay triangulation between segments, the unbounded one, the ones hole
/// points eat, and whether the domain is one of closed loops that pdd's loop-based code
/// (MADD, shielding, lfs) takes.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/errors.hpp>
#include <pdd/geometry/detail/loop_nesting.hpp>
#include <pdd/geometry/detail/loops.hpp>

#include <CGAL/Spatial_sort_traits_adapter_2.h>
#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <string>
#include <vector>

namespace pdd::detail {

/// A PSLG's constrained triangulation with every triangle labelled by its face, and which
/// faces are the domain by Triangle's rule.
struct pslg_faces {
  /// The triangulation (cdt_face_info::face set on every face, infinite ones included); the
  /// loops (structure) and nesting levels only when every vertex lies on two segments.
  loops_with_triangulation lt;
  /// By face id: 1 when the face is in the domain. Face 0 is the unbounded face.
  std::vector<char> face_in_domain;
  /// Every vertex lies on exactly two segments and the domain is the odd-nesting one (every
  /// region inside an even number >= 2 of loops holds a hole point, no other region does):
  /// the closed-loop domains pdd's loop-based code (MADD, shielding, lfs) takes.
  bool closed_loops = false;

  bool in_domain(pslg_cdt::Face_handle f) const { return face_in_domain[f->info().face] != 0; }
};

/// Numbers the faces of the arrangement: cdt_face_info::face of every triangle (infinite ones
/// too) is its piece of the triangulation joined across unconstrained edges, 0 for the piece
/// of the infinite face, then in the order of the finite faces. Returns the number of faces.
/// Complexity O(triangles).
inline index_t label_components(const pslg_cdt& cdt) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f)
    f->info().face = no_index;
  index_t n = 0;
  std::vector<pslg_cdt::Face_handle> stack;
  const auto flood = [&](pslg_cdt::Face_handle s) {
    s->info().face = n;
    stack.assign(1, s);
    while (!stack.empty()) {
      const pslg_cdt::Face_handle f = stack.back();
      stack.pop_back();
      for (int i = 0; i < 3; ++i) {
        const pslg_cdt::Face_handle nb = f->neighbor(i);
        if (f->is_constrained(i) || nb->info().face != no_index) continue;
        nb->info().face = n;
        stack.push_back(nb);
      }
    }
    ++n;
  };
  flood(cdt.infinite_face());
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->info().face == no_index) flood(f);
  return n;
}

/// The indices of g's hole points in spatial (Hilbert) order, so that each point location
/// can start from the face of the previous one.
inline std::vector<std::size_t> holes_in_spatial_order(const pslg& g,
                                                       std::vector<epick::Point_2>& pts) {
  for (const point& h : g.holes)
    pts.push_back(to_cgal(h));
  std::vector<std::size_t> order(pts.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  using pmap = CGAL::Pointer_property_map<epick::Point_2>::type;
  CGAL::spatial_sort(
      order.begin(), order.end(),
      CGAL::Spatial_sort_traits_adapter_2<epick, pmap>(CGAL::make_property_map(pts)));
  return order;
}

/// The face that hole point i, located in triangle f (lt_type, li as CGAL's locate), eats.
/// \throws geometry_error naming the hole point when it lies on a vertex, on a segment or in
/// the unbounded face.
inline index_t hole_face_of(const pslg& g, const pslg_cdt& cdt, std::size_t i,
                            pslg_cdt::Face_handle f, pslg_cdt::Locate_type lt_type, int li) {
  const std::string name = "hole point " + std::to_string(i) + " " + pdd::to_string(g.holes[i]);
  if (lt_type == pslg_cdt::VERTEX)
    throw geometry_error(
        name + " lies on vertex " + std::to_string(f->vertex(li)->info()) + ", on a segment", {i});
  if (lt_type == pslg_cdt::EDGE && f->is_constrained(li)) {
    const index_t a = f->vertex(pslg_cdt::cw(li))->info();
    const index_t b = f->vertex(pslg_cdt::ccw(li))->info();
    throw geometry_error(name + " lies on the segment between vertices " +
                             std::to_string(std::min(a, b)) + " and " +
                             std::to_string(std::max(a, b)),
                         {i});
  }
  if (cdt.is_infinite(f) || f->info().face == 0)
    throw geometry_error(name + " lies outside the domain (not inside any loop)", {i});
  return f->info().face;
}

/// Removes from the domain every face that holds a hole point. Point location with CGAL's
/// walk, hole points in spatial order with the previous triangle as hint.
inline void eat_holes(const pslg& g, pslg_faces& pf) {
  const pslg_cdt& cdt = pf.lt.triangulation.cdt;
  std::vector<epick::Point_2> pts;
  pslg_cdt::Face_handle hint;
  for (std::size_t i : holes_in_spatial_order(g, pts)) {
    pslg_cdt::Locate_type lt_type;
    int li = 0;
    const auto f = cdt.locate(pts[i], lt_type, li, hint);
    hint = f;
    pf.face_in_domain[hole_face_of(g, cdt, i, f, lt_type, li)] = 0;
  }
}

/// True when the domain by Triangle's rule is the odd-nesting one (see pslg_faces).
inline bool odd_nesting_agrees(const pslg_faces& pf) {
  const pslg_cdt& cdt = pf.lt.triangulation.cdt;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (pf.in_domain(f) != (f->info().level % 2 == 1)) return false;
  return true;
}

/// Builds the triangulation of g, labels its faces and applies the hole points (Triangle's
/// rule), whatever g.rule says. \pre g passed validate()'s segment checks (no duplicates, no
/// intersections). \throws geometry_error for a hole point on a vertex, on a segment or
/// outside every segment, or when no face is left in the domain.
/// Complexity O(n log n) expected.
inline void find_faces_into(const pslg& g, pslg_faces& pf) {
  const segment_incidence inc = incident_segments(g);
  const bool degree_two = !g.segments.empty() && std::all_of(inc.degree.begin(), inc.degree.end(),
                                                             [](index_t d) { return d == 2; });
  if (degree_two)
    find_loops_into(g, pf.lt); // the loops, the triangulation and the nesting levels
  else
    build_cdt(g, pf.lt.triangulation);
  const pslg_cdt& cdt = pf.lt.triangulation.cdt;
  if (cdt.dimension() < 2)
    throw empty_domain_error("the PSLG encloses no domain: all its vertices are collinear");
  pf.face_in_domain.assign(label_components(cdt), 1);
  pf.face_in_domain[0] = 0;
  eat_holes(g, pf);
  if (std::find(pf.face_in_domain.begin(), pf.face_in_domain.end(), 1) == pf.face_in_domain.end())
    throw empty_domain_error("the PSLG encloses no domain: no face is enclosed by segments, or "
                             "hole points eat every enclosed face");
  pf.closed_loops = degree_two && odd_nesting_agrees(pf);
}

/// Labels the faces of g's triangulation by g.rule without checking the hole points (a hole
/// point on a segment or outside the domain is ignored): odd_nesting as pdd's loop code
/// (needs closed loops), triangle as find_faces_into.
inline void faces_by_rule(const pslg& g, pslg_faces& pf) {
  if (g.rule == domain_rule::triangle) {
    find_faces_into(g, pf);
    return;
  }
  find_loops_into(g, pf.lt);
  const pslg_cdt& cdt = pf.lt.triangulation.cdt;
  pf.face_in_domain.assign(label_components(cdt), 0);
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (in_domain(f)) pf.face_in_domain[f->info().face] = 1;
  pf.closed_loops = true;
}

/// The area of the domain faces: the sum of their triangles' areas.
inline double faces_area(const pslg_faces& pf) {
  double area = 0.0;
  const pslg_cdt& cdt = pf.lt.triangulation.cdt;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (pf.in_domain(f))
      area +=
          std::abs(CGAL::area(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()));
  return area;
}

} // namespace pdd::detail
