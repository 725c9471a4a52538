/// \file compiled.hpp
/// What libpdd holds compiled: the stages of the chain (pipeline/chain.hpp) with the built-in
/// kernels (pdd::cgal::mesher, except in a PDD_PERMISSIVE build, and pdd::native::mesher), the
/// default partitioner and the TBB executor, every sink through pdd::mesh_sink_ref, and both
/// kernels for pdd::any_sizing and pdd::uniform_sizing, and pdd::decompose (MADD) with the default
/// partitioner. Outside a header-only build (PDD_HEADER_ONLY) they are declared here `extern
/// template`, so a program that includes the stages' templates does not compile these again: it
/// links them from libpdd. Other kernels, partitioners, executors and sizing fields are compiled
/// where they are used, as in a header-only build.
#pragma once

#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#ifndef PDD_PERMISSIVE
#include <pdd/kernels/cgal/mesher_templates.hpp>
#endif
#include <pdd/kernels/native/mesher_templates.hpp>
#include <pdd/madd/decompose.hpp>
#include <pdd/mesh/mesh_sink_ref.hpp>
#include <pdd/parallel/tbb_executor.hpp>
#include <pdd/partition/default_partitioner.hpp>
#include <pdd/pipeline/chain.hpp>
#include <pdd/sizing/any_sizing.hpp>
#include <pdd/sizing/uniform.hpp>

#include <cstddef>

/// The instantiations of kernel M that libpdd holds, each prefixed with PREFIX (`template` in
/// libpdd's sources, `extern template` here). Used in namespace pdd.
#define PDD_KERNEL_INSTANTIATIONS(PREFIX, M)                                                       \
  PREFIX mesher_result M::mesh<any_sizing>(const pslg&, const mesh_criteria&, const any_sizing&)   \
      const;                                                                                       \
  PREFIX mesher_result M::mesh<uniform_sizing>(const pslg&, const mesh_criteria&,                  \
                                               const uniform_sizing&) const;                       \
  PREFIX triangle_mesh mesh_whole_stage<M>(const planned_run&, const generate_options&, const M&,  \
                                           std::size_t&);                                          \
  PREFIX void mesh_stage<M, tbb_executor, mesh_sink_ref>(                                          \
      run_state&, const planned_run&, const generate_options&, const M&, const tbb_executor&,      \
      mesh_sink_ref&, generate_statistics&)

/// The instantiations of the decomposition stages that libpdd holds (see above), and MADD
/// (pdd::decompose) with the default partitioner, which the stages and pdd-decompose call.
#define PDD_STAGE_INSTANTIATIONS(PREFIX)                                                           \
  PREFIX decomposition decompose<default_partitioner>(const madd_start&, const madd_options&,      \
                                                      const default_partitioner&,                  \
                                                      decomposition_statistics*);                  \
  PREFIX decomposition decompose<default_partitioner>(                                             \
      const pslg&, const madd_options&, const default_partitioner&, decomposition_statistics*);    \
  PREFIX run_state decompose_stage<default_partitioner, tbb_executor>(                             \
      const run_plan&, const planned_run&, const generate_options&, const default_partitioner&,    \
      const tbb_executor&, generate_statistics&);                                                  \
  PREFIX run_state decouple_stage<default_partitioner, tbb_executor>(                              \
      run_state, const planned_run&, const generate_options&, const default_partitioner&,          \
      const tbb_executor&, generate_statistics&)

// explicit instantiation declarations (not API): hidden from Doxygen
/// \cond
#ifndef PDD_HEADER_ONLY
namespace pdd {
#ifndef PDD_PERMISSIVE
PDD_KERNEL_INSTANTIATIONS(extern template, cgal::mesher);
#endif
PDD_KERNEL_INSTANTIATIONS(extern template, native::mesher);
PDD_STAGE_INSTANTIATIONS(extern template);
} // namespace pdd
#endif
/// \endcond
