/// \file generate.hpp
/// pdd::generate: the one-call path of the uniform decoupling method (dissertation ch. 6):
/// decompose (MADD), decouple (Theorem 15, Lemma 9), mesh every subdomain in parallel and merge
/// (or stream to a MeshSink).
#pragma once

#include <pdd/concepts/delaunay_mesher.hpp>
#include <pdd/concepts/executor.hpp>
#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/kernels/cgal/mesher.hpp>
#include <pdd/mesh/merge.hpp>
#include <pdd/parallel/parallel_for.hpp>
#include <pdd/parallel/tbb_executor.hpp>
#include <pdd/partition/default_partitioner.hpp>
#include <pdd/pipeline.hpp>
#include <pdd/pipeline/system.hpp>

#include <chrono>
#include <utility>

namespace pdd {

/// The merged mesh and what it took.
struct generate_result {
  /// One conforming Delaunay mesh of the domain; triangle markers are subdomain ids (0 when
  /// N == 1); segments are the mesh edges on input segments with their markers.
  triangle_mesh mesh;
  /// What the run took: subdomain and triangle counts, times per phase, the decoupling's
  /// conditions (see generate_statistics).
  generate_statistics statistics;
};

namespace detail {
/// generate() on the calling thread's arena (see generate()).
template <DelaunayMesher M, GraphPartitioner P, Executor E>
generate_result generate_merged(const pslg& domain, const generate_options& options,
                                const M& mesher, const P& partitioner) {
  const auto t0 = std::chrono::steady_clock::now();
  pipeline<M, P, E> pl(domain, options, mesher, partitioner);
  pl.template check_memory<merge_sink>(); // up front, before any work
  generate_result r;
  r.mesh = pl.mesh_merged();
  r.statistics = std::move(pl.statistics());
  r.statistics.vertices = r.mesh.vertices.size();
  r.statistics.timings.total = seconds_since(t0);
  return r;
}
} // namespace detail

/// Meshes the domain of `domain` with guaranteed quality by the uniform decoupling method:
/// N subdomains by MADD (options.subdomains, 0: automatic_subdomains; 1: the kernel on the
/// whole domain), the decoupling path of Theorem 15, every subdomain meshed independently on
/// options.threads threads, the meshes merged in memory (merge_sink). The result is bitwise
/// the same for every thread count; with options.threads = T > 0 no part of the call (MADD, the
/// path, the kernel, the merge) runs on more than T threads (pdd::with_threads).
/// \tparam M a DelaunayMesher (default pdd::cgal::mesher). \tparam P a GraphPartitioner
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
template <DelaunayMesher M = cgal::mesher, GraphPartitioner P = default_partitioner,
          Executor E = tbb_executor>
generate_result generate(const pslg& domain, const generate_options& options = {},
                         const M& mesher = {}, const P& partitioner = {}) {
  return with_threads(options.threads, [&] {
    return detail::generate_merged<M, P, E>(domain, options, mesher, partitioner);
  });
}

/// As generate(), but delivers each subdomain mesh to `sink` as soon as it is done (e.g. a
/// vtu_directory_sink writes one file per subdomain and keeps nothing in memory, so meshes
/// larger than memory can be made). Returns the statistics.
/// \tparam S a MeshSink. \throws as generate().
template <DelaunayMesher M = cgal::mesher, GraphPartitioner P = default_partitioner,
          Executor E = tbb_executor, MeshSink S>
generate_statistics generate(const pslg& domain, const generate_options& options, S& sink,
                             const M& mesher = {}, const P& partitioner = {}) {
  return with_threads(options.threads, [&] {
    const auto t0 = std::chrono::steady_clock::now();
    pipeline<M, P, E> pl(domain, options, mesher, partitioner);
    pl.template check_memory<S>(); // up front, before any work
    pl.mesh(sink);
    generate_statistics st = std::move(pl.statistics());
    st.timings.total = seconds_since(t0);
    return st;
  });
}

} // namespace pdd
