/// \file domain_angles.hpp
/// pdd::domain_angles: the angles of a PSLG's domain between consecutive segments at its
/// vertices (Triangle's rule for the domain), internal and dangling constraints included.
#pragma once

#include <pdd/core/index.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/geometry/detail/face_angles.hpp>
#include <pdd/geometry/detail/pslg_faces.hpp>

#include <vector>

namespace pdd {

/// One sector of the domain at a vertex: turning counter-clockwise from the segment to vertex
/// `from` to the segment to vertex `to` (from == to: the one sector of a dangling end, 360 deg).
struct domain_angle {
  /// The PSLG vertex at the sector's apex.
  index_t vertex = no_index;
  /// The sector's angle in degrees, in (0, 360]; 360 for a dangling end.
  double angle_deg = 360.0;
  /// The vertex at the other end of the segment the sector starts from (counter-clockwise).
  index_t from = no_index;
  /// The vertex at the other end of the segment the sector ends at; == from at a dangling end.
  index_t to = no_index;
};

/// Every sector of g's domain (Triangle's rule, whatever g.rule says) between consecutive
/// segments at a vertex whose triangles lie in the domain, by vertex, counter-clockwise from the
/// first segment of each vertex in its triangulation. On closed loops these are the domain-side
/// angles of pdd::min_domain_angle_deg. \pre g valid (pdd::validate). \throws geometry_error as
/// pdd::validate. Complexity O(n log n) expected. Thread-safe.
inline std::vector<domain_angle> domain_angles(const pslg& g) {
  detail::pslg_faces pf;
  detail::find_faces_into(g, pf);
  std::vector<domain_angle> out;
  detail::for_each_domain_angle(g, pf, [&](index_t v, double a, index_t from, index_t to) {
    out.push_back({v, a, from, to});
  });
  return out;
}

} // namespace pdd
