/// \file mesh_subdomain.hpp
/// Implementation of pdd::mesh_subdomains: one subdomain job (kernel, invariance check,
/// delivery) and the invariance repair rounds.
#pragma once

#include <pdd/concepts/delaunay_mesher.hpp>
#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/decoupling/decoupled_decomposition.hpp>
#include <pdd/decoupling/invariance.hpp>
#include <pdd/errors.hpp>
#include <pdd/madd/subdomain_pslg.hpp>
#include <pdd/meshing/meshing_statistics.hpp>
#include <pdd/shielding/apply_shields.hpp>
#include <pdd/sizing/any_sizing.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <vector>

namespace pdd {

namespace detail {

/// The state of one mesh_subdomains call: the jobs read dd and write their own report slot;
/// failures and counters are shared under a mutex.
template <DelaunayMesher M, MeshSink S>
class meshing_run {
public:
  meshing_run(decoupled_decomposition& dd, const mesh_criteria& criteria, const any_sizing& sizing,
              const M& mesher, S& sink)
      : dd_(dd), criteria_(criteria), sizing_(sizing), mesher_(mesher), sink_(sink) {
    const auto m = dd.num_subdomains();
    stats.subdomains.resize(m);
    work.resize(m);
    const bool bounded = std::isfinite(criteria.max_area) && criteria.max_area > 0.0;
    for (index_t s = 0; s < m; ++s) {
      stats.subdomains[s].area = subdomain_area(dd.parts, s);
      work[s] = bounded ? stats.subdomains[s].area / criteria.max_area : stats.subdomains[s].area;
    }
  }

  /// Meshes subdomain s, checks its interface pieces and delivers it, or records the failure.
  /// \throws pdd::meshing_error(s, ...) for any exception inside.
  void mesh_one(index_t s) {
    try {
      const auto t0 = std::chrono::steady_clock::now();
      const subdomain_input in = dd_.input(s);
      mesher_result r = mesher_.mesh(in.domain, criteria_, sizing_);
      const std::vector<index_t> split = split_interface_pieces(in, r);
      subdomain_report& rep = stats.subdomains[s];
      rep.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      ++rep.runs;
      if (!split.empty()) return record_failure(s, in, split);
      if (s < dd_.shields.size() && !dd_.shields[s].empty()) {
        const std::size_t ss =
            add_shield_triangles(r, in.domain, dd_.shields[s], static_cast<int>(s));
        if (ss != 0) {
          {
            const std::lock_guard lock(mutex_);
            stats.shield_splits += ss;
          }
          throw meshing_error(s, std::to_string(ss) +
                                     " shield edge(s) were split by the kernel (Theorem 24 "
                                     "(5) excludes it for a Ruppert-type kernel)");
        }
      }
      rep.vertices = r.mesh.vertices.size();
      rep.triangles = r.mesh.triangles.size();
      r.mesh.triangle_markers.assign(r.mesh.triangles.size(), static_cast<int>(s));
      sink_.consume(s, std::move(r.mesh));
    } catch (const meshing_error& e) {
      if (e.subdomain() == static_cast<long long>(s)) throw;
      throw meshing_error(s, e.what());
    } catch (const std::exception& e) {
      throw meshing_error(s, e.what());
    }
  }

  bool has_failures() const { return !failures_.empty(); }

  /// Starts a repair round: re-splits every failing path edge with k / 2 and returns the
  /// subdomains to mesh again (the failing ones and their neighbours across those edges),
  /// sorted. \throws pdd::decoupling_error when max_repairs rounds have been used.
  std::vector<index_t> prepare_repair(unsigned max_repairs) {
    if (stats.repair_rounds >= max_repairs)
      throw decoupling_error("the decoupling path was split by the kernel and " +
                             std::to_string(max_repairs) +
                             " repair rounds did not fix it: " + describe_failures());
    ++stats.repair_rounds;
    std::set<index_t> redo, edges;
    for (const auto& [s, es] : failures_) {
      redo.insert(s);
      edges.insert(es.begin(), es.end());
    }
    for (const index_t e : edges) {
      dd_.resplit(e, dd_.path[e].k / 2.0);
      redo.insert(dd_.path[e].sides[0]);
      redo.insert(dd_.path[e].sides[1]);
    }
    failures_.clear();
    stats.remeshed_subdomains += redo.size();
    return {redo.begin(), redo.end()};
  }

  meshing_statistics stats;
  std::vector<double> work; ///< expected work per subdomain: area / max_area (or area)

private:
  void record_failure(index_t s, const subdomain_input& in, const std::vector<index_t>& split) {
    std::vector<index_t> edges;
    for (const index_t seg : split)
      edges.push_back(in.segment_path_edge[seg]);
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    const std::lock_guard lock(mutex_);
    stats.interface_splits += split.size();
    failures_[s] = std::move(edges);
  }

  std::string describe_failures() const {
    std::string msg;
    for (const auto& [s, edges] : failures_)
      for (const index_t e : edges)
        msg += (msg.empty() ? "" : "; ") + std::string("subdomain ") + std::to_string(s) +
               ", separator segment " + std::to_string(dd_.path[e].u) + "-" +
               std::to_string(dd_.path[e].v) + " (k " + std::to_string(dd_.path[e].k) + ")";
    return msg;
  }

  decoupled_decomposition& dd_;
  const mesh_criteria& criteria_;
  const any_sizing& sizing_;
  const M& mesher_;
  S& sink_;
  std::mutex mutex_;
  std::map<index_t, std::vector<index_t>> failures_; // subdomain -> failing path edges
};

} // namespace detail
} // namespace pdd
