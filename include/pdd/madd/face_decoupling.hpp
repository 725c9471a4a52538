/// \file face_decoupling.hpp
/// pdd::face_decoupling: the regions pdd::decompose starts from on a domain that is not one of
/// closed loops (issue 13): its faces, with caps where a small angle lies on a segment between
/// two of them.
#pragma once

#include <pdd/core/index.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/madd/detail/face_regions.hpp>

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace pdd {

/// What face_decoupling found.
struct face_decoupling_report {
  std::size_t faces = 0;   ///< faces of the domain
  std::size_t regions = 0; ///< regions MADD starts from (each is at least one subdomain)
  std::vector<std::pair<point, double>> caps; ///< each cap's apex and radius
  /// Empty without caps; else how many and why: a corner < 60 deg on a segment between two
  /// faces, or a segment inside a face at < 60 deg to one, gets a cap (a disc sector around
  /// its vertex, detail::cap_corners) that is one subdomain, so that no interface meets a small
  /// angle (the segment's piece lies inside the cap, whose kernel meshes the angle). Names the
  /// first vertex.
  std::string cap_reason;
};

/// The faces of g's domain (pdd::domain_faces by g.rule) as pdd::decompose starts from them
/// (dangling segments and isolated vertices kept inside regions, faces that touch themselves
/// at pinch vertices weakly simple, caps at small angles between faces).
/// \pre g is valid and not of closed loops (pdd::has_closed_loops false).
/// \throws pdd::geometry_error as pdd::domain_faces. Complexity O(n log n) expected.
/// Thread-safety: reentrant.
inline face_decoupling_report face_decoupling(const pslg& g) {
  detail::face_region_set f = detail::face_regions(g);
  return {f.faces, f.regions.size(), std::move(f.caps), std::move(f.cap_reason)};
}

} // namespace pdd
