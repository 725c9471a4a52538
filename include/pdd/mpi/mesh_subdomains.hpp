/// \file mesh_subdomains.hpp
/// pdd::mpi::mesh_subdomains: the mesh generation phase over the ranks of an MPI communicator
/// the caller owns (dissertation Algorithm 7.2, the master/worker scheme of 6.4 and 7.6):
/// rank 0 hands the subdomains out one at a time, largest expected work first, to whichever
/// rank asks; every rank meshes with its own oneTBB threads and delivers to its own sink.
#pragma once

#include <pdd/concepts/delaunay_mesher.hpp>
#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/decoupling/decoupled_decomposition.hpp>
#include <pdd/errors.hpp>
#include <pdd/meshing/mesh_subdomain.hpp>
#include <pdd/meshing/meshing_statistics.hpp>
#include <pdd/mpi/collectively.hpp>
#include <pdd/mpi/detail/meshing_rank.hpp>
#include <pdd/mpi/detail/wire.hpp>

#include <mpi.h>

#include <algorithm>
#include <cstddef>
#include <map>
#include <string>
#include <type_traits>
#include <vector>

namespace pdd::mpi {

/// What one rank did in pdd::mpi::mesh_subdomains.
struct rank_report {
  std::size_t meshings = 0;  ///< subdomain meshings it ran (repeated ones included)
  std::size_t triangles = 0; ///< triangles of the meshes it delivered (their last delivery)
  double busy_seconds = 0.0; ///< time of its meshings (kernel, check, sink), summed
};

/// Statistics of pdd::mpi::mesh_subdomains; the same on every rank.
struct distributed_meshing_statistics {
  /// As pdd::mesh_subdomains reports them; per subdomain, seconds and runs are summed over
  /// its meshings and vertices and triangles are those of its delivered mesh.
  meshing_statistics meshing;
  std::vector<int> subdomain_rank; ///< the rank that delivered each subdomain
  std::vector<rank_report> ranks;  ///< by rank

  /// Load imbalance: the largest busy_seconds over the mean (1: perfect balance; 0 when no
  /// rank was busy).
  double imbalance() const {
    double max = 0.0, sum = 0.0;
    for (const rank_report& r : ranks) {
      max = std::max(max, r.busy_seconds);
      sum += r.busy_seconds;
    }
    return sum > 0.0 ? max * static_cast<double>(ranks.size()) / sum : 0.0;
  }
};

namespace detail {

/// Adds a round's records to `stats` (every rank the same, in subdomain order) and returns the
/// invariance failures of the round (subdomain -> split path edges).
inline std::map<index_t, std::vector<index_t>>
merge_round(const std::vector<gathered_record>& records, distributed_meshing_statistics& stats) {
  std::map<index_t, std::vector<index_t>> failures;
  for (const gathered_record& g : records) {
    subdomain_report& rep = stats.meshing.subdomains[g.subdomain];
    rank_report& rr = stats.ranks[static_cast<std::size_t>(g.rank)];
    rep.seconds += g.seconds;
    ++rep.runs;
    ++rr.meshings;
    rr.busy_seconds += g.job_seconds;
    if (!g.split_path_edges.empty()) {
      stats.meshing.interface_splits += g.split_pieces;
      failures[g.subdomain] = g.split_path_edges;
      continue;
    }
    if (g.failure.kind != error_kind::none) continue;
    const int before = stats.subdomain_rank[g.subdomain];
    if (before >= 0) stats.ranks[static_cast<std::size_t>(before)].triangles -= rep.triangles;
    rep.vertices = g.vertices;
    rep.triangles = g.triangles;
    rr.triangles += g.triangles;
    stats.subdomain_rank[g.subdomain] = g.rank;
  }
  return failures;
}

/// The subdomains of the first round: [0, n) but the kept ones.
inline std::vector<index_t> first_round(std::size_t n, const std::vector<index_t>& kept) {
  std::vector<bool> skip(n, false);
  for (const index_t s : kept)
    if (s < n) skip[s] = true;
  std::vector<index_t> ids;
  for (index_t s = 0; s < n; ++s)
    if (!skip[s]) ids.push_back(s);
  return ids;
}

/// The failing record of the smallest subdomain id, or nullptr (the executors' rule: the
/// reported error does not depend on timing).
inline const gathered_record* first_failure(const std::vector<gathered_record>& records) {
  const gathered_record* first = nullptr;
  for (const gathered_record& g : records)
    if (g.failure.kind != error_kind::none && (!first || g.subdomain < first->subdomain))
      first = &g;
  return first;
}

/// An MPI_Comm_dup of the caller's communicator (the dispatcher's messages never meet the
/// caller's), freed at the end of the scope.
class private_comm {
public:
  explicit private_comm(MPI_Comm comm) { check(MPI_Comm_dup(comm, &comm_), "MPI_Comm_dup"); }
  ~private_comm() { MPI_Comm_free(&comm_); }
  private_comm(const private_comm&) = delete;
  private_comm& operator=(const private_comm&) = delete;
  MPI_Comm get() const noexcept { return comm_; }

private:
  MPI_Comm comm_ = MPI_COMM_NULL;
};

} // namespace detail

/// Meshes every subdomain of `dd` over the ranks of `comm` (Algorithm 7.2): the master (rank
/// 0) queues the subdomains in decreasing order of expected work (pdd::expected_work) and
/// sends the next one to whichever rank asks; every rank asks for one subdomain per free
/// thread of its own `threads` oneTBB threads (0: all cores), meshes it (pdd::mesh_subdomain:
/// the decoupling needs no communication, Theorem 15) and delivers it to its own `sink`
/// (sink.consume on the rank that meshed it; the mesh is the one the threaded
/// pdd::mesh_subdomains delivers, bitwise). sink.start(n) is called on every rank first, and
/// sink.finish() on every rank once all ranks have succeeded, in a collective step (see
/// pdd::mpi::collectively): a sink that writes an index of all subdomains writes it on one
/// rank in finish().
///
/// Invariance repairs (never needed with a Ruppert-type kernel) run as in
/// pdd::mesh_subdomains, on every rank's copy of dd alike: the ranks learn every failure.
/// \pre Collective: every rank of comm calls it with the same dd (built identically on every
/// rank: the decomposition and the decoupling path are deterministic) and options.
/// \tparam M a DelaunayMesher. \tparam S a MeshSink.
/// \throws on every rank the same error: pdd::meshing_error(id, ...) for the smallest failing
/// subdomain id when a kernel or a sink throws (after every subdomain ran; the rank where it
/// happened rethrows the original exception), pdd::decoupling_error when repairs run out.
/// finish() is then not called. MPI must be initialised with at least MPI_THREAD_FUNNELED and
/// called from the thread that initialised it.
/// The subdomains of options.kept (a resumed run's intact pieces) are not meshed in the first
/// round. With a `reporter` (pdd::mpi::resumable_piece_sink), reporter.report(id) runs on the
/// rank that delivered subdomain id, right after its sink.consume, and its bytes reach
/// reporter.recorded(id, bytes) on rank 0's calling thread as the piece completes (all of them
/// before finish(); when recorded throws, every rank throws its exception after the round).
/// Complexity: the kernel on every subdomain spread over the ranks; three messages per
/// subdomain and one all-gather of the job records per round.
template <DelaunayMesher M, MeshSink S, class R = detail::no_reports>
distributed_meshing_statistics mesh_subdomains(MPI_Comm comm, decoupled_decomposition& dd,
                                               const meshing_options& options, const M& mesher,
                                               unsigned threads, S& sink, R&& reporter = R{}) {
  const detail::private_comm own(comm);
  int size = 0;
  detail::check(MPI_Comm_size(own.get(), &size), "MPI_Comm_size");
  const std::size_t n = dd.num_subdomains();
  const std::vector<double> work = expected_work(dd, options);
  distributed_meshing_statistics stats;
  stats.meshing.subdomains.resize(n);
  for (index_t s = 0; s < n; ++s)
    stats.meshing.subdomains[s].area = pdd::detail::subdomain_area(dd.parts, s);
  stats.subdomain_rank.assign(n, -1);
  stats.ranks.resize(static_cast<std::size_t>(size));
  start_sink(sink, static_cast<index_t>(n));
  detail::meshing_rank<M, S, std::remove_reference_t<R>> rank(own.get(), dd, options, mesher, sink,
                                                              threads, reporter);
  std::vector<index_t> ids = detail::first_round(n, options.kept);
  for (;;) {
    const std::vector<detail::gathered_record> records = rank.round(ids, work);
    if (const detail::gathered_record* f = detail::first_failure(records)) {
      if (const std::exception_ptr mine = rank.local_failure(f->subdomain))
        std::rethrow_exception(mine);
      detail::rethrow(f->failure);
    }
    const auto failures = detail::merge_round(records, stats);
    if (failures.empty()) break;
    if (stats.meshing.repair_rounds >= options.max_repairs)
      throw decoupling_error("the decoupling path was split by the kernel and " +
                             std::to_string(options.max_repairs) +
                             " repair rounds did not fix it: " +
                             describe_path_failures(dd, failures, options.criteria));
    ++stats.meshing.repair_rounds;
    ids = repair_decoupling_path(dd, failures);
    stats.meshing.remeshed_subdomains += ids.size();
  }
  collectively(own.get(), [&] { sink.finish(); });
  return stats;
}

} // namespace pdd::mpi
