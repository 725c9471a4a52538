/// \file criteria.hpp
/// pdd::cgal::sizing_criteria: a criteria class for CGAL's Mesh_2 refinement levels that
/// combines CGAL's shape test with an area bound from any SizingField.
#pragma once

#include <pdd/concepts/sizing_field.hpp>
#include <pdd/core/triangle_measures.hpp>

#include <CGAL/Mesh_2/Face_badness.h>

#include <algorithm>
#include <cmath>

namespace pdd::cgal {

/// Badness of a face: sin^2 of its smallest angle, its area over its area bound, and its
/// shortest edge. Ordering (`q1 < q2`: q1 before q2 in a priority queue): faces over their
/// area bound first, largest excess first (as CGAL's Delaunay_mesh_size_criteria_2); then the
/// shortest edge first, the order of Triangle 1.6's queue. (pdd::cgal::mesher's own queue takes
/// the faces over their bound last in, first out instead, for locality: mesher_faces.hpp.) CGAL's
/// order, the smallest angle first, made many more triangles near the angle bounds Triangle is used
/// at (20,000 random points in the unit square, no area bound: 184,639 against Triangle's 142,125
/// at 32.5 deg), as in the native kernel (kernels/native/detail/refine.hpp, bad_queue).
struct face_quality {
  double sine = 1.0;     ///< sin^2 of the smallest angle
  double size = 0.0;     ///< area / area bound (0 when unbounded)
  double shortest = 0.0; ///< the squared length of the shortest edge
  /// True when this face is refined before q: a face over its area bound before one within
  /// it (the larger excess first), else the shorter shortest edge first.
  bool operator<(const face_quality& q) const noexcept {
    if (size > 1.0) return q.size > 1.0 ? size > q.size : true;
    if (q.size > 1.0) return false;
    return shortest < q.shortest;
  }
};

/// Mesh_2 criteria (the interface of CGAL's Delaunay_mesh_criteria_2: `Quality`, `Is_bad`,
/// `is_bad_object()`). A face is bad when sin^2 of its smallest angle is below
/// `shape_bound` (B = sin^2(theta_min), 0.125 for 20.7 deg: the same shape measure as
/// CGAL's Delaunay_mesh_criteria_2, not the sin^2/4 of Delaunay_mesh_area_criteria_2), and
/// imperatively bad when its area exceeds min(max_area, sizing.area_at(centroid))
/// (dissertation eq. 1.1: the area bound of the sizing function).
/// \tparam Tr a CGAL triangulation whose points have x() and y().
/// \tparam S a SizingField; the criteria keep a pointer to it: it must outlive the meshing.
/// Thread-safety: const use from one mesher; many instances may run concurrently.
template <class Tr, SizingField S>
class sizing_criteria {
public:
  /// The triangulation's face handle (what Is_bad classifies).
  using Face_handle = typename Tr::Face_handle;
  /// A face's badness measures (CGAL's criteria interface).
  using Quality = face_quality;

  /// Criteria with the shape bound B = sin^2(theta_min) (0.125 for 20.7 deg; 0: no angle
  /// bound), the global area bound `max_area` (infinity: none) and the field `sizing`, which
  /// is kept by pointer and must outlive the criteria.
  sizing_criteria(double shape_bound, double max_area, const S& sizing)
      : shape_bound_(shape_bound), max_area_(max_area), sizing_(&sizing) {}

  /// B = sin^2 of the smallest angle allowed: a face below it is bad.
  double shape_bound() const noexcept { return shape_bound_; }
  /// The global area bound, applied with the field's (infinity: none but the field's).
  double max_area() const noexcept { return max_area_; }

  /// The area bound at a point: min(max_area, sizing.area_at(p)).
  double area_bound(const point& p) const {
    return std::min(max_area_, static_cast<double>(sizing_->area_at(p)));
  }

  /// The queue priority of a bad face (smaller first), in the order of face_quality::operator<:
  /// -size for a face over its area bound, else the squared length of its shortest edge.
  static double priority(const Quality& q) noexcept { return q.size > 1.0 ? -q.size : q.shortest; }
  /// The badness of a bad face from its priority.
  static CGAL::Mesh_2::Face_badness badness_of_priority(double key) noexcept {
    return key < 0.0 ? CGAL::Mesh_2::IMPERATIVELY_BAD : CGAL::Mesh_2::BAD;
  }

  /// CGAL's functor: classifies a face and fills its quality.
  class Is_bad {
  public:
    /// A functor over the criteria `c`, which must outlive it.
    explicit Is_bad(const sizing_criteria& c) : c_(&c) {}

    /// The badness of a face from its quality q: IMPERATIVELY_BAD over its area bound
    /// (q.size > 1), else BAD below the shape bound, else NOT_BAD.
    CGAL::Mesh_2::Face_badness operator()(const Quality& q) const {
      if (q.size > 1.0) return CGAL::Mesh_2::IMPERATIVELY_BAD;
      if (q.sine < c_->shape_bound_) return CGAL::Mesh_2::BAD;
      return CGAL::Mesh_2::NOT_BAD;
    }

    /// Measures face fh into q (area over the bound at its centroid, 0 when unbounded; sin^2
    /// of its smallest angle; its squared shortest edge) and returns its badness as
    /// operator()(q).
    CGAL::Mesh_2::Face_badness operator()(const Face_handle& fh, Quality& q) const {
      const point a = to_point(fh->vertex(0)->point());
      const point b = to_point(fh->vertex(1)->point());
      const point c = to_point(fh->vertex(2)->point());
      const double bound = c_->area_bound(detail::triangle_centroid(a, b, c));
      q.size = std::isinf(bound) ? 0.0 : detail::triangle_area(a, b, c) / bound;
      q.sine = detail::squared_sine_min_angle(a, b, c);
      const auto squared = [](const point& p, const point& r) {
        return (p.x - r.x) * (p.x - r.x) + (p.y - r.y) * (p.y - r.y);
      };
      q.shortest = std::min({squared(a, b), squared(b, c), squared(c, a)});
      return (*this)(q);
    }

  private:
    template <class P>
    static point to_point(const P& p) {
      return {p.x(), p.y()};
    }
    const sizing_criteria* c_;
  };

  /// The Is_bad functor of these criteria (CGAL's criteria interface); it refers to them.
  Is_bad is_bad_object() const { return Is_bad(*this); }

private:
  double shape_bound_;
  double max_area_;
  const S* sizing_;
};

} // namespace pdd::cgal
