/// \file mesher_faces.hpp
/// The face level of pdd::cgal::mesher: CGAL Mesh_2's Refine_faces with the bad-face queue
/// replaced by a stack of the faces over their area bound (last in, first out) and a binary heap
/// of the skinny ones, both with lazy deletion.
///
/// CGAL 5.5 keeps bad faces in a Double_map (a Boost bimap ordered by quality and by the
/// faces' point coordinates) and erases every face of every conflict zone from it: that took
/// about two thirds of the meshing time. Here a face is pushed once, when it is created (or at
/// the initial scan), with a copy of its vertex handles; entries whose face has since been
/// destroyed are skipped when they reach the top. A destroyed face is recognised because both
/// refinement levels clear the in_domain mark of every face of a conflict zone before the
/// zone is re-triangulated (and Compact_container keeps the memory of erased faces), and a
/// reused face slot is recognised by its vertices; a slot reused for the same three vertices
/// is the same triangle, with the same quality, so its entry stays valid.
/// Ties in quality are broken by insertion order, so the refinement order is deterministic.
///
/// Faces over their area bound are refined last in, first out, before any skinny face: the new
/// faces of an insertion next, depth first, each region down to its bound while it is in
/// cache. The heap's order, the largest excess first, refined the whole domain one halving of
/// the area at a time, each sweep over cold memory (the native kernel's queue had the same
/// order and the same cost, kernels/native/detail/refine.hpp).
#pragma once

#include <CGAL/Mesh_2/Face_badness.h>
#include <CGAL/Mesher_level.h>
#include <CGAL/Mesher_level_default_implementations.h>
#include <CGAL/Meshes/Triangulation_mesher_level_traits_2.h>

#include <pdd/errors.hpp>
#include <pdd/kernels/detail/off_centre.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <sstream>
#include <vector>

namespace pdd::detail::cgal_mesh {

template <class Tr, class Criteria, class Previous>
class faces_base : public CGAL::Triangulation_mesher_level_traits_2<Tr>,
                   public CGAL::No_test_point_conflict,
                   public CGAL::No_after_no_insertion {
  using traits = CGAL::Triangulation_mesher_level_traits_2<Tr>;
  using Face_handle = typename Tr::Face_handle;
  using Vertex_handle = typename Tr::Vertex_handle;
  using Point = typename Tr::Point;
  using Quality = typename Criteria::Quality;

public:
  using Zone = typename traits::Zone;
  using traits::triangulation_ref_impl;

  faces_base(Tr& t, Criteria& c, Previous& p) : traits(t), criteria_(c), previous_(p) {}

  /// Queues every bad face of the domain.
  void scan_triangulation_impl() {
    heap_.clear();
    over_area_.clear();
    Tr& t = triangulation_ref_impl();
    heap_.reserve(t.number_of_faces());
    for (auto f = t.finite_faces_begin(); f != t.finite_faces_end(); ++f)
      if (f->is_in_domain()) push_if_bad(f);
  }

  /// The conflict zone of p, the refinement point of fh: CGAL's (from the face that contains
  /// p) under the diametral disk, where Ruppert's lemma puts every such p in sight of fh. Under
  /// the lens p may lie beyond a segment, so the zone grows from fh itself, and the segment
  /// that hides p is on its boundary, where the edge level finds it (domain_gabriel::hides).
  Zone conflicts_zone_impl(const Point& p, Face_handle fh) {
    Zone zone;
    Tr& t = triangulation_ref_impl();
    zone.fh = t.locate(p, zone.locate_type, zone.i, fh);
    zone.parent_face = fh;
    if (previous_.lens_rule_in_use() == nullptr) {
      t.get_conflicts_and_boundary(p, std::back_inserter(zone.faces),
                                   std::back_inserter(zone.boundary_edges), fh);
      return zone;
    }
    zone.faces.push_back(fh);
    auto out =
        std::make_pair(std::back_inserter(zone.faces), std::back_inserter(zone.boundary_edges));
    for (int i = 0; i < 3; ++i)
      out = t.propagate_conflicts(p, fh, i, out);
    return zone;
  }

  bool no_longer_element_to_refine_impl() {
    drop_stale();
    return over_area_.empty() && heap_.empty();
  }

  Face_handle get_next_element_impl() {
    drop_stale();
    const entry& e = over_area_.empty() ? heap_.front() : over_area_.back();
    current_badness_ = Criteria::badness_of_priority(e.key);
    return e.f;
  }

  void pop_next_element_impl() {
    if (!over_area_.empty()) {
      over_area_.pop_back();
      return;
    }
    std::pop_heap(heap_.begin(), heap_.end(), after);
    heap_.pop_back();
  }

  /// The point that refines f: its off-centre (off_centre) where that is nearer to f's
  /// shortest edge than its circumcentre, else the circumcentre. \throws
  /// unresolvable_input_error naming f's corners when f is so flat that its circumcentre is not
  /// finite in double precision (CGAL divides by the determinant of its edge vectors; the
  /// release build would go on with a NaN point).
  Point refinement_point_impl(const Face_handle& f) const {
    const Point &p = f->vertex(0)->point(), &q = f->vertex(1)->point(), &r = f->vertex(2)->point();
    const double qx = q.x() - p.x(), qy = q.y() - p.y(), rx = r.x() - p.x(), ry = r.y() - p.y();
    const bool flat = qx * ry - qy * rx == 0.0;
    const Point c = flat ? p : triangulation_ref_impl().circumcenter(f);
    if (flat || !std::isfinite(c.x()) || !std::isfinite(c.y())) {
      std::ostringstream what;
      what.precision(17);
      what << "the triangle (" << p << "), (" << q << "), (" << r
           << ") is too flat to refine: its circumcentre is not finite in double precision (an "
              "input angle or feature too small to resolve)";
      throw unresolvable_input_error(-1, what.str());
    }
    return off_centre(f, c);
  }

  /// detail::off_centre of f (kernels/detail/off_centre.hpp) with its circumcentre c under the
  /// criteria's shape bound.
  Point off_centre(const Face_handle& f, const Point& c) const {
    const auto at = [&](int i) {
      return point{f->vertex(i)->point().x(), f->vertex(i)->point().y()};
    };
    const point o =
        detail::off_centre(at(0), at(1), at(2), point{c.x(), c.y()}, criteria_.shape_bound());
    return o.x == c.x() && o.y == c.y() ? c : Point(o.x, o.y);
  }

  void before_conflicts_impl(const Face_handle&, const Point&) {
    previous_.set_imperative_refinement(current_badness_ == CGAL::Mesh_2::IMPERATIVELY_BAD);
  }

  /// The faces of the zone are about to be destroyed: clear their marks (their queue entries
  /// become stale).
  void before_insertion_impl(const Face_handle&, const Point&, Zone& zone) {
    for (const Face_handle& f : zone.faces)
      f->set_in_domain(false);
  }

  void after_insertion_impl(const Vertex_handle& v) {
    auto fc = triangulation_ref_impl().incident_faces(v);
    const auto begin = fc;
    do {
      fc->set_in_domain(true);
    } while (++fc != begin);
    compute_new_bad_faces(v);
  }

  /// Queues the bad faces of the domain around v (called by CGAL's edge-level visitor too);
  /// those over their area bound the smallest excess first, so that the largest is refined
  /// first (the pipe at 4M triangles: 4,065,671 against 4,095,732 in fan order; Triangle
  /// 4,067,653).
  void compute_new_bad_faces(const Vertex_handle& v) {
    Tr& t = triangulation_ref_impl();
    auto fc = t.incident_faces(v);
    const auto begin = fc;
    new_over_area_.clear();
    do {
      if (!t.is_infinite(fc) && fc->is_in_domain()) push_if_bad(fc, &new_over_area_);
    } while (++fc != begin);
    std::sort(new_over_area_.begin(), new_over_area_.end(),
              [](const entry& x, const entry& y) { return x.key > y.key; });
    over_area_.insert(over_area_.end(), new_over_area_.begin(), new_over_area_.end());
  }

  CGAL::Mesh_2::Face_badness is_bad(const Quality& q) const { return criteria_.is_bad_object()(q); }

private:
  struct entry {
    double key; ///< Criteria::priority: smaller is refined first
    std::uint64_t seq;
    Face_handle f;
    std::array<Vertex_handle, 3> v;
  };
  /// Heap order: x comes after y (y is refined first).
  static bool after(const entry& x, const entry& y) {
    return x.key != y.key ? x.key > y.key : x.seq > y.seq;
  }

  /// Queues f if it is bad: over its area bound on `over_area` (the stack unless given),
  /// skinny on the heap.
  void push_if_bad(const Face_handle& f, std::vector<entry>* over_area = nullptr) {
    Quality q;
    const CGAL::Mesh_2::Face_badness badness = criteria_.is_bad_object()(f, q);
    if (badness == CGAL::Mesh_2::NOT_BAD) return;
    const entry e{Criteria::priority(q), seq_++, f, {f->vertex(0), f->vertex(1), f->vertex(2)}};
    if (badness == CGAL::Mesh_2::IMPERATIVELY_BAD) {
      (over_area != nullptr ? *over_area : over_area_).push_back(e);
      return;
    }
    heap_.push_back(e);
    std::push_heap(heap_.begin(), heap_.end(), after);
  }

  static bool stale(const entry& e) {
    return !e.f->is_in_domain() || e.f->vertex(0) != e.v[0] || e.f->vertex(1) != e.v[1] ||
           e.f->vertex(2) != e.v[2];
  }

  void drop_stale() {
    while (!over_area_.empty() && stale(over_area_.back()))
      over_area_.pop_back();
    if (!over_area_.empty()) return;
    while (!heap_.empty() && stale(heap_.front()))
      pop_next_element_impl();
  }

  Criteria& criteria_;
  Previous& previous_;
  std::vector<entry> over_area_;     ///< faces over their area bound: last in, first out
  std::vector<entry> new_over_area_; ///< compute_new_bad_faces' scratch
  std::vector<entry> heap_;          ///< skinny faces: the shortest edge first
  std::uint64_t seq_ = 0;
  CGAL::Mesh_2::Face_badness current_badness_ = CGAL::Mesh_2::NOT_BAD;
};

/// The face level: faces_base plus CGAL's Mesher_level driver.
template <class Tr, class Criteria, class Previous>
class faces_level
    : public faces_base<Tr, Criteria, Previous>,
      public CGAL::Mesher_level<Tr, faces_level<Tr, Criteria, Previous>, typename Tr::Face_handle,
                                Previous, CGAL::Triangulation_mesher_level_traits_2<Tr>> {
  using base = faces_base<Tr, Criteria, Previous>;
  using mesher = CGAL::Mesher_level<Tr, faces_level, typename Tr::Face_handle, Previous,
                                    CGAL::Triangulation_mesher_level_traits_2<Tr>>;

public:
  using Triangulation = Tr;
  using Previous_level = Previous;
  using Zone = typename base::Zone;
  using base::triangulation_ref_impl;

  faces_level(Tr& t, Criteria& c, Previous& p) : base(t, c, p), mesher(p) {}
};

} // namespace pdd::detail::cgal_mesh
