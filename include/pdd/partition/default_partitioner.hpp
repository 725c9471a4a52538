/// \file default_partitioner.hpp
/// pdd::default_partitioner: the GraphPartitioner the library uses unless told otherwise:
/// pdd::metis_partitioner when METIS was found (PDD_HAVE_METIS), else pdd::boost_partitioner.
#pragma once

#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/partition/boost_partitioner.hpp>
#include <pdd/partition/metis.hpp>

namespace pdd {

#ifdef PDD_HAVE_METIS
/// The default GraphPartitioner: METIS (the dissertation's choice, section 5.1).
using default_partitioner = metis_partitioner;
#else
/// The default GraphPartitioner: multilevel bisection with Boost.Graph only (no METIS found).
using default_partitioner = boost_partitioner;
#endif
static_assert(GraphPartitioner<default_partitioner>);

} // namespace pdd
