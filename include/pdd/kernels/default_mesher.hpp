/// \file default_mesher.hpp
/// pdd::default_mesher: the kernel pdd::generate and pdd::pipeline use unless told otherwise.
/// CGAL's Mesh_2 (pdd::cgal::mesher); in a PDD_PERMISSIVE build, which compiles no GPL package
/// of CGAL, pdd::native::mesher.
#pragma once

#ifdef PDD_PERMISSIVE
#include <pdd/kernels/native/mesher.hpp>
#else
#include <pdd/kernels/cgal/mesher.hpp>
#endif

namespace pdd {

#ifdef PDD_PERMISSIVE
/// The default kernel of this build: pdd::native::mesher (PDD_PERMISSIVE).
using default_mesher = native::mesher;
#else
/// The default kernel of this build: pdd::cgal::mesher (CGAL's Mesh_2).
using default_mesher = cgal::mesher;
#endif

} // namespace pdd
