/// \file pipeline.hpp
/// pdd::pipeline: the decoupling method in stages (MADD -> decoupling path -> parallel meshing
/// -> sink), thin over its plan (pipeline/run_plan.hpp: pdd::plan_run decides the path once)
/// and the chain of values that runs it (pipeline/chain.hpp). Its options, statistics and
/// planning rules are in pipeline/options.hpp, pipeline/statistics.hpp and
/// pipeline/planning.hpp; pdd::generate (generate.hpp) is the one-call path.
#pragma once

#include <pdd/concepts/delaunay_mesher.hpp>
#include <pdd/concepts/executor.hpp>
#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/core/decomposition.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/decoupling/decoupled_decomposition.hpp>
#include <pdd/errors.hpp>
#include <pdd/kernels/default_mesher.hpp>
#include <pdd/kernels/native/mesher.hpp>
#include <pdd/mesh/merge.hpp>
#include <pdd/mesh/mesh_sink_ref.hpp>
#include <pdd/meshing/mesh_subdomain.hpp>
#include <pdd/parallel/tbb_executor.hpp>
#include <pdd/partition/default_partitioner.hpp>
#include <pdd/pipeline/chain.hpp>
#include <pdd/pipeline/compiled.hpp>
#include <pdd/pipeline/detail/memory_check.hpp>
#include <pdd/pipeline/detail/plan.hpp>
#include <pdd/pipeline/options.hpp>
#include <pdd/pipeline/planning.hpp>
#include <pdd/pipeline/run_plan.hpp>
#include <pdd/pipeline/statistics.hpp>
#include <pdd/pipeline/system.hpp>
#include <pdd/sizing/mesh_size_estimate.hpp>

#include <chrono>
#include <cstddef>
#include <optional>
#include <utility>
#include <vector>

namespace pdd {

/// The decoupling pipeline in stages (dissertation 6.4, Algorithm 6.1; 7.4-7.5):
/// decompose() runs MADD into N subdomains, decouple() computes k_i per subdomain and the
/// graded decoupling path (Theorem 22, Lemma 9; one k where k is set), mesh(sink) meshes every
/// subdomain independently on the executor and streams the meshes to a MeshSink. Each stage
/// runs the earlier ones if needed; its results can be inspected (and changed) before the next.
/// With N = 1 there is no decomposition: mesh() runs the kernel on the whole domain and
/// delivers it as subdomain 0. The path is decided once, by plan() (pdd::plan_run), and changed
/// only by the plans a stage returns (pdd::whole_domain_plan, pdd::plan_after_path).
/// \tparam M a DelaunayMesher. \tparam P a GraphPartitioner. \tparam E an Executor (built from
/// options.threads when it takes a thread count).
/// Thread-safety: one pipeline object is used from one thread (its stages run in parallel
/// inside).
template <DelaunayMesher M = default_mesher, GraphPartitioner P = default_partitioner,
          Executor E = tbb_executor>
class pipeline {
public:
  /// Checks the options (check_generate_options) and plans the run (pdd::plan_run: the domain
  /// validated once, the mesh size estimated, N and the path chosen with their reason).
  /// \throws pdd::decomposition_error for contradicting options; pdd::geometry_error for an
  /// invalid domain.
  pipeline(pslg domain, generate_options options, M mesher = {}, P partitioner = {});

  /// The plan in force: plan_run's, or after a stage the fallback's or the retry's.
  const run_plan& plan() const noexcept { return state_ ? state_->plan : run_.plan; }

  /// True when the domain is not one of closed loops (pdd::has_closed_loops): Triangle's rule,
  /// decoupled from its faces or meshed whole (statistics().plan_reason says which).
  bool general_domain() const noexcept { return run_.plan.general_domain; }

  /// N, the number of subdomains this pipeline uses.
  std::size_t subdomains() const noexcept { return stats_.subdomains; }
  /// The options the pipeline runs with, as given (checked by check_generate_options).
  const generate_options& options() const noexcept { return options_; }
  /// The domain as read (Triangle's rule where it is not one of closed loops).
  const pslg& domain() const noexcept { return run_.domain; }

  /// \throws pdd::limit_error when meshing into a sink of type S would exceed
  /// options.max_triangles, or (max_triangles 0, check_memory) physical memory (kept in memory
  /// or not, see sink_retains_meshes and estimate_peak_bytes), or 32-bit indices in a kept
  /// mesh; the message gives the estimate, the feature that causes it and the memory needed.
  template <MeshSink S>
  void check_memory() const {
    check_memory(sink_retains_meshes<S>);
  }
  /// As check_memory<S>(), for a sink that keeps its meshes in memory or not
  /// (`retains_meshes`, pdd::sink_retains_meshes).
  void check_memory(bool retains_meshes) const;

  /// Subdomains mesh() does not mesh in its first round: their meshes exist already (a
  /// resumed run's intact pieces; generate_options::kept_subdomains).
  void keep_subdomains(std::vector<index_t> ids) { options_.kept_subdomains = std::move(ids); }

  /// The size estimate the plan uses (pdd::estimate_mesh_size) and its cause.
  const mesh_size_estimate& size_estimate() const noexcept { return run_.plan.estimate; }

  /// Stage 1 (pdd::decompose_stage): MADD into N subdomains (nothing when N == 1; the
  /// decomposition is then empty). \throws pdd::decomposition_error when the domain cannot be
  /// split as asked.
  const decomposition& decompose();

  /// Stage 2 (pdd::decouple_stage): the decoupling path (runs decompose() first if needed).
  /// Empty when N == 1, including after an automatic plan's fallback
  /// (statistics().monolithic_fallback). \throws as pdd::decouple.
  const decoupled_decomposition& decouple();

  /// Stage 3 (pdd::mesh_stage): meshes every subdomain (runs decouple() first if needed) and
  /// delivers the meshes to `sink` (see pdd::mesh_subdomains; N == 1: the whole domain as
  /// subdomain 0). \throws pdd::limit_error (`check_memory<S>()`), pdd::meshing_error with the
  /// subdomain id, pdd::decoupling_error when invariance repairs run out.
  template <MeshSink S>
  const generate_statistics& mesh(S& sink) {
    mesh_sink_ref ref(sink); // a mesh_sink_ref is copied, not wrapped again
    return mesh_into(ref);
  }

  /// mesh() into the sink `sink` refers to: every sink goes through this one function, so the
  /// meshing stage is compiled once per kernel (libpdd holds it for the built-in ones).
  const generate_statistics& mesh_into(mesh_sink_ref& sink);

  /// The merged mesh: mesh() into a merge_sink, or for N == 1 the kernel's own output (no
  /// copy through a sink). \throws as mesh().
  triangle_mesh mesh_merged();

  /// The triangles the size check plans for: the estimate (pdd::estimate_mesh_size), plus, once
  /// the decoupling path exists, 4 per split point (the kernel grades out from the separators).
  double planned_triangles() const noexcept {
    return stats_.estimated_triangles + 4.0 * static_cast<double>(stats_.split_points);
  }

  /// The kernel on the whole domain (the N == 1 path, pdd::mesh_whole_stage), markers 0. Input
  /// angles < 60 deg are shielded first (pdd::shield, Algorithm 8.2 with N = 1): the kernel
  /// meshes D' and the shielded triangles are added as they are.
  /// \throws pdd::meshing_error(-1, ...) from the kernel, or when it split a shield edge;
  /// pdd::geometry_error as pdd::shield.
  triangle_mesh mesh_whole() const {
    std::size_t shielded = 0;
    return mesh_whole(shielded);
  }
  /// As mesh_whole(); `shielded_triangles` receives the number of shielded triangles.
  triangle_mesh mesh_whole(std::size_t& shielded_triangles) const;

  /// The kernel's options for the subdomains (after decouple(): the path's field and order of
  /// work; pdd::meshing_options_for), for meshing them elsewhere (e.g. over MPI ranks).
  meshing_options meshing();

  /// The statistics so far.
  const generate_statistics& statistics() const noexcept { return stats_; }
  /// The statistics so far, for a caller that runs a stage elsewhere (e.g. meshes the
  /// subdomains over MPI ranks) to record what it did.
  generate_statistics& statistics() noexcept { return stats_; }
  /// The decoupled decomposition (after decouple(); may be changed before mesh()).
  decoupled_decomposition& decoupled() noexcept {
    PDD_ASSERT(decoupled_);
    return state_->path;
  }
  /// The executor the stages run on: E{options().threads} when E takes a thread count, else E{}.
  const E& executor() const noexcept { return executor_; }

private:
  static generate_options checked(generate_options o);

  generate_options options_;
  M mesher_;
  P partitioner_;
  E executor_;
  planned_run run_;                ///< the domain as read, MADD's regions and the first plan
  std::optional<run_state> state_; ///< the chain's value after decompose() / decouple()
  bool decoupled_ = false;
  generate_statistics stats_;
};

// The members that run the stages, out of the class: not inline, so that a program that uses
// pipeline with the built-in kernels, partitioner and executor links them from libpdd (declared
// `extern template` below) instead of compiling the stages' callers again.

template <DelaunayMesher M, GraphPartitioner P, Executor E>
pipeline<M, P, E>::pipeline(pslg domain, generate_options options, M mesher, P partitioner)
    : options_(checked(std::move(options))), mesher_(std::move(mesher)),
      partitioner_(std::move(partitioner)), executor_(detail::make_executor<E>(options_.threads)),
      run_(plan_run(std::move(domain), options_, executor_.concurrency())),
      stats_(planned_statistics(run_.plan, executor_.concurrency())) {}

template <DelaunayMesher M, GraphPartitioner P, Executor E>
void pipeline<M, P, E>::check_memory(bool retains_meshes) const {
  detail::check_size_plan({.triangles = planned_triangles(),
                           .estimate = &run_.plan.estimate,
                           .domain = &run_.domain,
                           .subdomains = stats_.subdomains,
                           .threads = stats_.threads,
                           .retains_meshes = retains_meshes,
                           .max_triangles = options_.max_triangles,
                           .check_memory = options_.check_memory});
}

template <DelaunayMesher M, GraphPartitioner P, Executor E>
const decomposition& pipeline<M, P, E>::decompose() {
  if (state_) return state_->parts;
  const auto t0 = std::chrono::steady_clock::now();
  state_ = decompose_stage(run_.plan, run_, options_, partitioner_, executor_, stats_);
  if (state_->plan.path != mesh_path::geometric) run_.regions.reset(); // not needed again
  stats_.timings.decompose = seconds_since(t0);
  return state_->parts;
}

template <DelaunayMesher M, GraphPartitioner P, Executor E>
const decoupled_decomposition& pipeline<M, P, E>::decouple() {
  if (decoupled_) return state_->path;
  decompose();
  const auto t0 = std::chrono::steady_clock::now();
  const double decompose_before = stats_.timings.decompose; // a second MADD run adds to it
  state_ = decouple_stage(std::move(*state_), run_, options_, partitioner_, executor_, stats_);
  run_.regions.reset(); // MADD's regions are not needed again
  stats_.timings.decouple = seconds_since(t0) - (stats_.timings.decompose - decompose_before);
  decoupled_ = true;
  return state_->path;
}

template <DelaunayMesher M, GraphPartitioner P, Executor E>
const generate_statistics& pipeline<M, P, E>::mesh_into(mesh_sink_ref& sink) {
  decouple();
  check_memory(sink.referred_retains_meshes());
  const auto t0 = std::chrono::steady_clock::now();
  mesh_stage(*state_, run_, options_, mesher_, executor_, sink, stats_);
  stats_.timings.mesh = seconds_since(t0) - stats_.timings.merge;
  const generate_timings& t = stats_.timings;
  stats_.timings.total = t.decompose + t.decouple + t.mesh + t.merge;
  return stats_;
}

template <DelaunayMesher M, GraphPartitioner P, Executor E>
triangle_mesh pipeline<M, P, E>::mesh_merged() {
  decouple();
  if (stats_.subdomains > 1) {
    merge_sink sink(options_.threads);
    mesh(sink);
    return sink.take();
  }
  check_memory<merge_sink>();
  const auto t0 = std::chrono::steady_clock::now();
  triangle_mesh m = mesh_whole(stats_.shielded_triangles);
  stats_.timings.mesh = seconds_since(t0);
  stats_.triangles = m.triangles.size();
  return m;
}

template <DelaunayMesher M, GraphPartitioner P, Executor E>
triangle_mesh pipeline<M, P, E>::mesh_whole(std::size_t& shielded_triangles) const {
  return mesh_whole_stage(run_, options_, mesher_, shielded_triangles);
}

template <DelaunayMesher M, GraphPartitioner P, Executor E>
meshing_options pipeline<M, P, E>::meshing() {
  decouple();
  return meshing_options_for(*state_, options_);
}

template <DelaunayMesher M, GraphPartitioner P, Executor E>
generate_options pipeline<M, P, E>::checked(generate_options o) {
  check_generate_options(o);
  return o;
}

// explicit instantiation declarations (not API): hidden from Doxygen
/// \cond
#ifndef PDD_HEADER_ONLY
#ifndef PDD_PERMISSIVE
extern template class pipeline<cgal::mesher, default_partitioner, tbb_executor>;
#endif
extern template class pipeline<native::mesher, default_partitioner, tbb_executor>;
#endif
/// \endcond

} // namespace pdd
