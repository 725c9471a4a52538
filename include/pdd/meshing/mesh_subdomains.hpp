/// \file mesh_subdomains.hpp
/// pdd::mesh_subdomains: meshes every subdomain of a decoupled decomposition independently on
/// an Executor, checks the decoupling path's invariance (Corollary 13), repairs it if it ever
/// fails, and hands each mesh to a MeshSink (dissertation 6.4, Algorithm 6.1 steps 7-8).
#pragma once

#include <pdd/concepts/delaunay_mesher.hpp>
#include <pdd/concepts/executor.hpp>
#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/decoupling/decoupled_decomposition.hpp>
#include <pdd/errors.hpp>
#include <pdd/meshing/detail/mesh_subdomain.hpp>
#include <pdd/meshing/mesh_subdomain.hpp>
#include <pdd/sizing/any_sizing.hpp>

#include <utility>
#include <vector>

namespace pdd {

/// Meshes each subdomain's input() with `mesher` under `options.criteria`, concurrently on
/// `executor` (largest expected work, area / max_area, first), and delivers every mesh whose
/// interface pieces are all still edges (Corollary 13; see split_interface_pieces) to
/// `sink.consume(id, mesh)` with triangle markers set to the id; calls sink.start(n) first
/// (when the sink has it) and sink.finish() at the end. The subdomains of options.kept (whose
/// meshes the sink has from an earlier run) are not meshed in the first round.
///
/// Invariance repair (never needed when the kernel is Ruppert-type and the decomposition meets
/// the method's preconditions): a subdomain with a split interface piece is not delivered;
/// after the round, every separator segment with a split piece is re-split with k / 2, and the
/// subdomain and its neighbours across those segments are meshed again (neighbours already
/// delivered are delivered again, replacing their mesh), up to options.max_repairs rounds.
/// \tparam M a DelaunayMesher. \tparam E an Executor. \tparam S a MeshSink.
/// \throws pdd::meshing_error(id, ...) for the smallest failing subdomain id when the kernel
/// (or the sink, with a meshing_error or an exception that is no pdd::error) throws; a sink's
/// other pdd::error (an output it cannot write) as the sink threw it; pdd::decoupling_error naming
/// subdomains and segments when repairs run out. After an exception, finish() has not been called
/// and the sink holds partial results. Complexity: the kernel on every subdomain, plus linear
/// checks.
template <DelaunayMesher M, Executor E, MeshSink S>
meshing_statistics mesh_subdomains(decoupled_decomposition& dd, const meshing_options& options,
                                   const M& mesher, const E& executor, S& sink) {
  detail::meshing_run<M, S> run(dd, options, mesher, sink);
  const auto m = static_cast<index_t>(dd.num_subdomains());
  start_sink(sink, m);
  const auto mesh_these = [&](const std::vector<index_t>& ids) {
    std::vector<double> work(ids.size());
    for (std::size_t j = 0; j < ids.size(); ++j)
      work[j] = run.work[ids[j]];
    executor.run(work, [&](index_t j) { run.mesh_one(ids[j]); });
  };
  if (options.kept.empty()) {
    executor.run(run.work, [&](index_t s) { run.mesh_one(s); });
  } else {
    std::vector<bool> kept(m, false);
    for (const index_t s : options.kept)
      if (s < m) kept[s] = true;
    std::vector<index_t> ids;
    for (index_t s = 0; s < m; ++s)
      if (!kept[s]) ids.push_back(s);
    mesh_these(ids);
  }
  while (run.has_failures())
    mesh_these(run.prepare_repair(options.max_repairs));
  sink.finish();
  return std::move(run.stats);
}

} // namespace pdd
