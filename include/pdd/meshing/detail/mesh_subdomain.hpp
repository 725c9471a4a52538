/// \file mesh_subdomain.hpp
/// Implementation of pdd::mesh_subdomains: one subdomain job (kernel, invariance check,
/// delivery) and the invariance repair rounds.
#pragma once

#include <pdd/concepts/delaunay_mesher.hpp>
#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/decoupling/decoupled_decomposition.hpp>
#include <pdd/errors.hpp>
#include <pdd/madd/subdomain_pslg.hpp>
#include <pdd/meshing/mesh_subdomain.hpp>
#include <pdd/meshing/meshing_statistics.hpp>

#include <exception>
#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace pdd {

namespace detail {

/// The state of one mesh_subdomains call: the jobs read dd and write their own report slot;
/// failures and counters are shared under a mutex.
template <DelaunayMesher M, MeshSink S>
class meshing_run {
public:
  meshing_run(decoupled_decomposition& dd, const meshing_options& options, const M& mesher, S& sink)
      : work(expected_work(dd, options)), dd_(dd), options_(options), mesher_(mesher), sink_(sink) {
    stats.subdomains.resize(work.size());
    for (index_t s = 0; s < work.size(); ++s)
      stats.subdomains[s].area = subdomain_area(dd.parts, s);
  }

  /// Meshes subdomain s (pdd::mesh_subdomain) and delivers it, or records the failure.
  /// \throws pdd::meshing_error(s, ...) for any exception inside, except a pdd::error of the
  /// sink that is not a meshing_error (an output it cannot write: a full disk, a missing
  /// directory), which is rethrown as it is: the input and the kernel are not at fault.
  void mesh_one(index_t s) {
    subdomain_meshing r = mesh_subdomain(dd_, s, options_, mesher_);
    subdomain_report& rep = stats.subdomains[s];
    rep.seconds += r.seconds;
    ++rep.runs;
    if (!r.split_path_edges.empty()) return record_failure(s, r);
    rep.vertices = r.mesh.vertices.size();
    rep.triangles = r.mesh.triangles.size();
    try {
      sink_.consume(s, std::move(r.mesh));
    } catch (const meshing_error& e) {
      rethrow_for_subdomain(e, static_cast<long long>(s));
    } catch (const error&) {
      throw; // the sink's own error (its output), named by the sink
    } catch (const std::exception& e) {
      throw meshing_error(s, e.what());
    }
  }

  bool has_failures() const { return !failures_.empty(); }

  /// Starts a repair round (pdd::repair_decoupling_path) and returns the subdomains to mesh
  /// again. \throws pdd::decoupling_error when max_repairs rounds have been used.
  std::vector<index_t> prepare_repair(unsigned max_repairs) {
    if (stats.repair_rounds >= max_repairs)
      throw decoupling_error("the decoupling path was split by the kernel and " +
                             std::to_string(max_repairs) + " repair rounds did not fix it: " +
                             describe_path_failures(dd_, failures_, options_.criteria));
    ++stats.repair_rounds;
    std::vector<index_t> redo = repair_decoupling_path(dd_, failures_);
    failures_.clear();
    stats.remeshed_subdomains += redo.size();
    return redo;
  }

  std::vector<double> work; ///< expected work per subdomain (pdd::expected_work)
  meshing_statistics stats;

private:
  void record_failure(index_t s, subdomain_meshing& r) {
    const std::lock_guard lock(mutex_);
    stats.interface_splits += r.split_pieces.size();
    failures_[s] = std::move(r.split_path_edges);
  }

  decoupled_decomposition& dd_;
  const meshing_options& options_;
  const M& mesher_;
  S& sink_;
  std::mutex mutex_;
  std::map<index_t, std::vector<index_t>> failures_; // subdomain -> failing path edges
};

} // namespace detail
} // namespace pdd
