/// \file face_decoupling.hpp
/// pdd::face_decoupling: whether pdd::decompose can start from the faces of a domain that is
/// not one of closed loops (issue 13), how many there are, and if not, why.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/madd/detail/face_regions.hpp>

#include <cstddef>
#include <string>
#include <utility>

namespace pdd {

/// What face_decoupling found.
struct face_decoupling_report {
  std::size_t faces = 0; ///< faces of the domain (each is at least one subdomain); 0 if refused
  /// Empty when MADD can start from the faces (dangling segments and isolated vertices are
  /// kept inside subdomains, faces that touch themselves at pinch vertices are weakly simple);
  /// else the first reason it cannot (a corner < 60 deg on a segment between two faces, a
  /// segment inside a face that starts at the apex of a corner < 60 deg or at < 60 deg to a
  /// segment between two faces), naming the vertex ids.
  std::string refusal;
};

/// The faces of g's domain (pdd::domain_faces by g.rule) as pdd::decompose starts from them.
/// \pre g is valid and not of closed loops (pdd::has_closed_loops false).
/// \throws pdd::geometry_error as pdd::domain_faces. Complexity O(n log n) expected.
/// Thread-safety: reentrant.
inline face_decoupling_report face_decoupling(const pslg& g) {
  detail::face_region_set f = detail::face_regions(g);
  return {f.regions.size(), std::move(f.refusal)};
}

} // namespace pdd
