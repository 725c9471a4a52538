/// \file domain_gabriel.hpp
/// The CGAL kernel's vertex data and its segment encroachment test (pdd::cgal::mesher): the
/// diametral disk seen from the domain only, and Triangle's diametral lens on input segments
/// (pdd::segment_encroachment).
#pragma once

#include <pdd/core/index.hpp>
#include <pdd/core/point.hpp>
#include <pdd/kernels/detail/encroachment.hpp>

#include <CGAL/enum.h>

#include <limits>

namespace pdd::detail::cgal_mesh {

inline constexpr index_t none = std::numeric_limits<index_t>::max();

/// Per-vertex data: the input index (or `none` for a Steiner vertex until numbered) and, for
/// a Steiner vertex on an input segment, the input endpoints of that segment.
struct vertex_info {
  index_t id = none;
  index_t seg_a = none;
  index_t seg_b = none;
};

/// The diametral lens rule of the CGAL kernel (segment_encroachment::diametral_lens), set
/// where uses_diametral_lens holds.
struct lens_rule {
  double cosine; ///< mesh_criteria::lens_cosine
};

/// Gabriel test of a constrained edge seen from the domain only: the edge is encroached when
/// the apex of an adjacent face that is in the domain lies in its closed diametral disk
/// (CGAL's Is_locally_conforming_Gabriel tests both sides; a vertex beyond the domain, e.g.
/// across a notch of a subdomain, must not split an interface segment) and, with a lens rule,
/// in its diametral lens too.
template <class Tr>
struct domain_gabriel {
  using Vertex_handle = typename Tr::Vertex_handle;
  using Face_handle = typename Tr::Face_handle;
  using Point = typename Tr::Point;

  /// Set under segment_encroachment::diametral_lens; null: the disk alone.
  const lens_rule* lens = nullptr;

  bool operator()(const Tr& tr, const Face_handle& fh, int i) const {
    const Vertex_handle& va = fh->vertex(Tr::cw(i));
    const Vertex_handle& vb = fh->vertex(Tr::ccw(i));
    const Face_handle nb = fh->neighbor(i);
    const Vertex_handle& vi = fh->vertex(i);
    const Vertex_handle& mvi = tr.tds().mirror_vertex(fh, i);
    if (fh->is_in_domain() && !tr.is_infinite(vi) && !(*this)(tr, va, vb, vi->point()))
      return false;
    if (nb->is_in_domain() && !tr.is_infinite(mvi) && !(*this)(tr, va, vb, mvi->point()))
      return false;
    return true;
  }

  bool operator()(const Tr& tr, const Vertex_handle& va, const Vertex_handle& vb) const {
    Face_handle fh;
    int i = 0;
    const bool is_edge = tr.is_edge(va, vb, fh, i);
    CGAL_assume(is_edge);
    return (*this)(tr, fh, i);
  }

  bool operator()(const Tr& tr, const Face_handle& fh, int i, const Point& p) const {
    return (*this)(tr, fh->vertex(Tr::cw(i)), fh->vertex(Tr::ccw(i)), p);
  }

  /// p is outside the diametral disk of [va, vb] (exact: the angle va p vb is acute), or,
  /// with a lens rule, outside its lens.
  bool operator()(const Tr& tr, const Vertex_handle& va, const Vertex_handle& vb,
                  const Point& p) const {
    if (tr.geom_traits().angle_2_object()(va->point(), p, vb->point()) == CGAL::ACUTE) return true;
    if (lens == nullptr) return false;
    const point a{va->point().x(), va->point().y()}, b{vb->point().x(), vb->point().y()};
    return !in_diametral_lens(a, b, point{p.x(), p.y()}, lens->cosine);
  }

  /// With a lens rule: the constrained edge (fh, i) on the boundary of the conflict zone of p,
  /// given from the face outside the zone as CGAL gives it, hides p from the zone (p is not
  /// strictly on the zone's side). Under the disk alone this cannot happen (Ruppert's lemma:
  /// such a p is in the disk), under the lens it can, and it counts as encroachment.
  bool hides(const Tr& tr, const Face_handle& fh, int i, const Point& p) const {
    if (lens == nullptr) return false;
    const Vertex_handle& mirror = tr.tds().mirror_vertex(fh, i);
    if (tr.is_infinite(mirror)) return true;
    const auto orient = tr.geom_traits().orientation_2_object();
    const Point& a = fh->vertex(Tr::cw(i))->point();
    const Point& b = fh->vertex(Tr::ccw(i))->point();
    const CGAL::Orientation side = orient(a, b, mirror->point());
    return side == CGAL::COLLINEAR || orient(a, b, p) != side;
  }
};

} // namespace pdd::detail::cgal_mesh
