/// \file meshing_rank.hpp
/// Implementation of pdd::mpi::mesh_subdomains: one rank's part of a meshing round (its jobs
/// and what they did) and the all-gather that tells every rank what every job did.
#pragma once

#include <pdd/concepts/delaunay_mesher.hpp>
#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/decoupling/decoupled_decomposition.hpp>
#include <pdd/errors.hpp>
#include <pdd/meshing/mesh_subdomain.hpp>
#include <pdd/meshing/meshing_statistics.hpp>
#include <pdd/mpi/collectively.hpp>
#include <pdd/mpi/detail/dispatcher.hpp>
#include <pdd/mpi/detail/wire.hpp>

#include <mpi.h>

#include <chrono>
#include <cstdint>
#include <exception>
#include <map>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace pdd::mpi::detail {

/// What one job (one subdomain meshing) did, on the rank that ran it.
struct job_record {
  bool here = false; ///< this rank ran the job
  std::uint64_t vertices = 0, triangles = 0, split_pieces = 0;
  double seconds = 0.0;                  ///< kernel and check (pdd::mesh_subdomain)
  double job_seconds = 0.0;              ///< the whole job: kernel, check and delivery to the sink
  std::vector<index_t> split_path_edges; ///< non-empty: not delivered (Corollary 13 failed)
  std::exception_ptr failure;            ///< the job's exception (the kernel's or the sink's)
};

/// A job record as every rank learns it: the subdomain, the rank and the record's data.
struct gathered_record {
  index_t subdomain = 0;
  int rank = 0;
  std::uint64_t vertices = 0, triangles = 0, split_pieces = 0;
  double seconds = 0.0, job_seconds = 0.0;
  std::vector<index_t> split_path_edges;
  wire_error failure;
};

/// The reporter of a pdd::mpi::mesh_subdomains whose master records nothing.
struct no_reports {
  std::string report(index_t) const { return {}; }
  void recorded(index_t, std::string_view) const {}
};

/// One rank's side of pdd::mpi::mesh_subdomains: meshes the subdomains the dispatcher hands it
/// (pdd::mesh_subdomain), delivers the good ones to its own sink, records every job, and
/// passes each delivered piece's reporter.report(id) to reporter.recorded(id, bytes) on the
/// master as it completes.
template <DelaunayMesher M, MeshSink S, class R = no_reports>
class meshing_rank {
public:
  meshing_rank(MPI_Comm comm, const decoupled_decomposition& dd, const meshing_options& options,
               const M& mesher, S& sink, unsigned threads, R& reporter)
      : comm_(comm), dd_(dd), options_(options), mesher_(mesher), sink_(sink), reporter_(reporter),
        dispatcher_(comm, threads) {}

  /// Meshes the subdomains `ids` over all ranks (collective, the same ids everywhere) and
  /// returns every job's record, in the order of ids, on every rank. \throws on every rank
  /// when the master's reporter.recorded threw (the master's exception).
  std::vector<gathered_record> round(const std::vector<index_t>& ids,
                                     const std::vector<double>& all_work) {
    ids_ = ids;
    records_.assign(ids.size(), job_record{});
    std::vector<double> work(ids.size());
    for (std::size_t j = 0; j < ids.size(); ++j)
      work[j] = all_work[ids[j]];
    auto job = [this](index_t j) { return mesh_one(j); };
    std::exception_ptr failure; // the master's: recorded() threw
    auto done = [&](index_t j, std::string_view bytes) {
      if (bytes.empty() || failure) return;
      try {
        reporter_.recorded(ids_[j], bytes);
      } catch (...) {
        failure = std::current_exception();
      }
    };
    dispatcher_.run(work, job, done);
    if constexpr (!std::is_same_v<R, no_reports>) rethrow_first_failure(comm_, failure);
    return gather();
  }

  /// This rank's exception of the job for subdomain `s` in the last round (null: none here).
  std::exception_ptr local_failure(index_t s) const {
    for (std::size_t j = 0; j < ids_.size(); ++j)
      if (ids_[j] == s && records_[j].here) return records_[j].failure;
    return nullptr;
  }

private:
  /// Job j of the round: subdomain ids_[j]; returns the reporter's report of its delivered
  /// piece (empty when it was not delivered). Never throws (records the exception).
  std::string mesh_one(index_t j) {
    job_record& rec = records_[j];
    rec.here = true;
    const index_t s = ids_[j];
    const auto t0 = std::chrono::steady_clock::now();
    std::string report;
    try {
      subdomain_meshing r = mesh_subdomain(dd_, s, options_, mesher_);
      rec.seconds = r.seconds;
      rec.split_pieces = r.split_pieces.size();
      rec.split_path_edges = std::move(r.split_path_edges);
      if (rec.split_path_edges.empty()) {
        rec.vertices = r.mesh.vertices.size();
        rec.triangles = r.mesh.triangles.size();
        deliver(s, std::move(r.mesh));
        report = reporter_.report(s);
      }
    } catch (...) {
      rec.failure = std::current_exception();
      report.clear();
    }
    rec.job_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return report;
  }

  /// The sink's consume; its exceptions become pdd::meshing_error(s, ...) as in
  /// pdd::mesh_subdomains.
  void deliver(index_t s, triangle_mesh&& mesh) {
    try {
      sink_.consume(s, std::move(mesh));
    } catch (const meshing_error& e) {
      rethrow_for_subdomain(e, static_cast<long long>(s));
    } catch (const std::exception& e) {
      throw meshing_error(s, e.what());
    }
  }

  /// Every rank's records of this round, on every rank (one all-gather).
  std::vector<gathered_record> gather() const {
    byte_writer w;
    for (std::size_t j = 0; j < ids_.size(); ++j) {
      const job_record& rec = records_[j];
      if (!rec.here) continue;
      w.put(static_cast<std::uint64_t>(j));
      w.put(rec.vertices);
      w.put(rec.triangles);
      w.put(rec.split_pieces);
      w.put(rec.seconds);
      w.put(rec.job_seconds);
      w.put(static_cast<std::uint64_t>(rec.split_path_edges.size()));
      for (const index_t e : rec.split_path_edges)
        w.put(e);
      put(w, encode(rec.failure));
    }
    const std::vector<std::string> all = all_gather_bytes(comm_, w.bytes);
    std::vector<gathered_record> out(ids_.size());
    for (std::size_t r = 0; r < all.size(); ++r)
      for (byte_reader in(all[r]); !in.done();)
        read_record(in, static_cast<int>(r), out);
    return out;
  }

  void read_record(byte_reader& in, int rank, std::vector<gathered_record>& out) const {
    const auto j = static_cast<std::size_t>(in.get<std::uint64_t>());
    if (j >= out.size()) throw internal_error("pdd::mpi: a job record out of range");
    gathered_record& g = out[j];
    g.subdomain = ids_[j];
    g.rank = rank;
    g.vertices = in.get<std::uint64_t>();
    g.triangles = in.get<std::uint64_t>();
    g.split_pieces = in.get<std::uint64_t>();
    g.seconds = in.get<double>();
    g.job_seconds = in.get<double>();
    g.split_path_edges.resize(static_cast<std::size_t>(in.get<std::uint64_t>()));
    for (index_t& e : g.split_path_edges)
      e = in.get<index_t>();
    g.failure = get_error(in);
  }

  MPI_Comm comm_;
  const decoupled_decomposition& dd_;
  const meshing_options& options_;
  const M& mesher_;
  S& sink_;
  R& reporter_;
  dispatcher dispatcher_;
  std::vector<index_t> ids_;
  std::vector<job_record> records_; // by position in ids_; slot j written by job j only
};

} // namespace pdd::mpi::detail
