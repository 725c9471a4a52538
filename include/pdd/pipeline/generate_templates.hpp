/// \file generate_templates.hpp
/// The definitions of the functions pdd::generate calls (pipeline/generate_entry.hpp), over
/// pdd::pipeline. libpdd holds them for pdd::cgal::mesher (not in a PDD_PERMISSIVE build) and
/// pdd::native::mesher with the
/// default partitioner and the TBB executor (declared `extern template` here outside a
/// header-only build); include this header to call pdd::generate with types of your own.
#pragma once

#ifndef PDD_PERMISSIVE
#include <pdd/kernels/cgal/mesher.hpp>
#endif
#include <pdd/kernels/native/mesher.hpp>
#include <pdd/mesh/merge.hpp>
#include <pdd/mesh/mesh_sink_ref.hpp>
#include <pdd/parallel/parallel_for.hpp>
#include <pdd/parallel/tbb_executor.hpp>
#include <pdd/partition/default_partitioner.hpp>
#include <pdd/pipeline.hpp>
#include <pdd/pipeline/generate_entry.hpp>
#include <pdd/pipeline/system.hpp>

#include <chrono>
#include <utility>

namespace pdd::detail {

template <DelaunayMesher M, GraphPartitioner P, Executor E>
generate_result generate_merged(const pslg& domain, const generate_options& options,
                                const M& mesher, const P& partitioner) {
  return with_threads(options.threads, [&] {
    const auto t0 = std::chrono::steady_clock::now();
    pipeline<M, P, E> pl(domain, options, mesher, partitioner);
    pl.template check_memory<merge_sink>(); // up front, before any work
    generate_result r;
    r.mesh = pl.mesh_merged();
    r.statistics = std::move(pl.statistics());
    r.statistics.vertices = r.mesh.vertices.size();
    r.statistics.timings.total = seconds_since(t0);
    return r;
  });
}

template <DelaunayMesher M, GraphPartitioner P, Executor E>
generate_statistics generate_into(const pslg& domain, const generate_options& options,
                                  mesh_sink_ref sink, const M& mesher, const P& partitioner) {
  return with_threads(options.threads, [&] {
    const auto t0 = std::chrono::steady_clock::now();
    pipeline<M, P, E> pl(domain, options, mesher, partitioner);
    pl.check_memory(sink.referred_retains_meshes()); // up front, before any work
    pl.mesh_into(sink);
    generate_statistics st = std::move(pl.statistics());
    st.timings.total = seconds_since(t0);
    return st;
  });
}

} // namespace pdd::detail

/// The instantiations of pdd::generate's functions that libpdd holds for kernel M, each
/// prefixed with PREFIX (`template` in libpdd's sources, `extern template` here).
#define PDD_GENERATE_INSTANTIATIONS(PREFIX, M)                                                     \
  PREFIX generate_result detail::generate_merged<M, default_partitioner, tbb_executor>(            \
      const pslg&, const generate_options&, const M&, const default_partitioner&);                 \
  PREFIX generate_statistics detail::generate_into<M, default_partitioner, tbb_executor>(          \
      const pslg&, const generate_options&, mesh_sink_ref, const M&, const default_partitioner&)

// explicit instantiation declarations (not API): hidden from Doxygen
/// \cond
#ifndef PDD_HEADER_ONLY
namespace pdd {
#ifndef PDD_PERMISSIVE
PDD_GENERATE_INSTANTIATIONS(extern template, cgal::mesher);
#endif
PDD_GENERATE_INSTANTIATIONS(extern template, native::mesher);
} // namespace pdd
#endif
/// \endcond
