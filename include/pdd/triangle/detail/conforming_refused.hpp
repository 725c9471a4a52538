/// \file conforming_refused.hpp
/// Switches D and S with q or a in a PDD_PERMISSIVE build: refused. They mesh on CGAL's Mesh_2
/// (conforming.hpp), which that build leaves out (GPL).
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/sizing/any_sizing.hpp>
#include <pdd/triangle/switches.hpp>
#include <pdd/triangle/triangulation.hpp>

#include <string>

namespace pdd::triangle::detail {

/// \throws switch_error: this build has no conforming Delaunay mesher.
inline triangulation conforming_mesh(const pslg&, const switches& sw, const any_sizing&) {
  throw switch_error(std::string(sw.conforming ? "switch -D (conforming Delaunay)"
                                               : "switch -S with -q or -a (a Steiner budget)") +
                     " needs CGAL's Mesh_2, which this build of pdd leaves out (PDD_PERMISSIVE: "
                     "no GPL code); use a default build of pdd for it");
}

} // namespace pdd::triangle::detail
