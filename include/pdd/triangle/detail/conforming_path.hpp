/// \file conforming_path.hpp
/// Whether pdd::triangle::triangulate takes the conforming path (switch D, or S with q or a).
#pragma once

#include <pdd/triangle/switches.hpp>

namespace pdd::triangle::detail {

/// True when the switches take the conforming path: D, or S with q or a (S alone adds nothing:
/// the constrained Delaunay triangulation has no Steiner point).
inline bool conforming_path(const switches& sw) {
  return sw.conforming || (sw.quality && sw.max_steiner >= 0);
}

} // namespace pdd::triangle::detail
