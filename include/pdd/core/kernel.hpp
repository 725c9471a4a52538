/// \file kernel.hpp
/// pdd::epick: the CGAL kernel every pdd module computes with (exact predicates, inexact
/// constructions), named once.
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace pdd {

/// CGAL's Exact_predicates_inexact_constructions_kernel: orientation, in-circle and
/// intersection tests are exact (filtered), constructed points are rounded doubles.
using epick = CGAL::Exact_predicates_inexact_constructions_kernel;

} // namespace pdd
