/// \file generate.hpp
/// pdd::generate: the one-call path of the uniform decoupling method (dissertation ch. 6):
/// decompose (MADD), decouple (Theorem 15, Lemma 9), mesh every subdomain in parallel and merge
/// (or stream to a MeshSink).
///
/// This header is light: libpdd holds pdd::generate compiled for pdd::cgal::mesher (not in a
/// PDD_PERMISSIVE build) and pdd::native::mesher with the default partitioner and the TBB executor,
/// for any sink. A program that calls it with a kernel, partitioner or executor of its own also
/// includes <pdd/pipeline/generate_templates.hpp> (in a header-only build, PDD_HEADER_ONLY, this
/// header includes it).
#pragma once

#include <pdd/concepts/delaunay_mesher.hpp>
#include <pdd/concepts/executor.hpp>
#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/kernels/default_mesher.hpp>
#include <pdd/mesh/mesh_sink_ref.hpp>
#include <pdd/parallel/tbb_executor.hpp>
#include <pdd/partition/default_partitioner.hpp>
#include <pdd/pipeline/generate_entry.hpp>
#include <pdd/pipeline/options.hpp>
#include <pdd/pipeline/statistics.hpp>

namespace pdd {

/// Meshes the domain of `domain` with guaranteed quality by the uniform decoupling method:
/// N subdomains by MADD (options.subdomains, 0: automatic_subdomains; 1: the kernel on the
/// whole domain), the decoupling path of Theorem 15, every subdomain meshed independently on
/// options.threads threads, the meshes merged in memory (merge_sink). The result is bitwise
/// the same for every thread count; with options.threads = T > 0 no part of the call (MADD, the
/// path, the kernel, the merge) runs on more than T threads (pdd::with_threads).
/// \tparam M a DelaunayMesher (default pdd::default_mesher: CGAL's Mesh_2, or the native
/// kernel in a PDD_PERMISSIVE build). \tparam P a GraphPartitioner
/// (default METIS when found). \tparam E an Executor (default pdd::tbb_executor).
/// \pre `domain` is valid (pdd::validate). Input angles < 60 deg are shielded (dissertation
/// 8.1, pdd::shield / pdd::shield_decomposition; with a sizing field and N > 1 per subdomain
/// with Theorem 26's l_i, pdd::shield_graded_decomposition): each becomes one shielded triangle of
/// the mesh, with the input angle as its smallest angle; every other triangle meets the criteria.
/// \throws pdd::geometry_error (invalid domain), pdd::limit_error (the mesh would not fit in
/// memory: the message has the estimate), pdd::decomposition_error (MADD; also, up front,
/// options.madd.min_separator_angle_deg outside [60, 90)), pdd::meshing_error (kernel, with
/// the subdomain id), pdd::decoupling_error (invariance repairs exhausted).
/// Complexity: the kernel on every subdomain plus O(mesh size) merging.
template <DelaunayMesher M = default_mesher, GraphPartitioner P = default_partitioner,
          Executor E = tbb_executor>
generate_result generate(const pslg& domain, const generate_options& options = {},
                         const M& mesher = {}, const P& partitioner = {}) {
  return detail::generate_merged<M, P, E>(domain, options, mesher, partitioner);
}

/// As generate(), but delivers each subdomain mesh to `sink` as soon as it is done (e.g. a
/// vtu_directory_sink writes one file per subdomain and keeps nothing in memory, so meshes
/// larger than memory can be made). Returns the statistics.
/// \tparam S a MeshSink. \throws as generate().
template <DelaunayMesher M = default_mesher, GraphPartitioner P = default_partitioner,
          Executor E = tbb_executor, MeshSink S>
generate_statistics generate(const pslg& domain, const generate_options& options, S& sink,
                             const M& mesher = {}, const P& partitioner = {}) {
  return detail::generate_into<M, P, E>(domain, options, mesh_sink_ref(sink), mesher, partitioner);
}

} // namespace pdd

#ifdef PDD_HEADER_ONLY
#include <pdd/pipeline/generate_templates.hpp>
#endif
