/// \file default_mesher_templates.hpp
/// The template definitions of pdd::default_mesher (kernels/cgal/mesher_templates.hpp, or
/// kernels/native/mesher_templates.hpp in a PDD_PERMISSIVE build): include it to mesh with the
/// default kernel under a sizing field of your own (libpdd holds the kernels for
/// pdd::any_sizing and pdd::uniform_sizing only).
#pragma once

#include <pdd/kernels/default_mesher.hpp>

#ifdef PDD_PERMISSIVE
#include <pdd/kernels/native/mesher_templates.hpp>
#else
#include <pdd/kernels/cgal/mesher_templates.hpp>
#endif
