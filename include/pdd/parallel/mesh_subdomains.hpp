/// \file mesh_subdomains.hpp
/// pdd::mesh_subdomains: meshes every subdomain of a decoupled decomposition independently on
/// an Executor, checks the decoupling path's invariance (Corollary 13), repairs it if it ever
/// fails, and hands each mesh to a MeshSink (dissertation 6.4, Algorithm 6.1 steps 7-8).
#pragma once

#include <pdd/concepts/delaunay_mesher.hpp>
#include <pdd/concepts/executor.hpp>
#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/decoupling/decoupled_decomposition.hpp>
#include <pdd/decoupling/invariance.hpp>
#include <pdd/detail/decoupling_loops.hpp>
#include <pdd/errors.hpp>
#include <pdd/mesh/criteria.hpp>
#include <pdd/sizing/uniform.hpp>

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

/// Options of pdd::mesh_subdomains.
struct meshing_options {
  mesh_criteria criteria;   ///< the same criteria the decoupling path was built for
  unsigned max_repairs = 3; ///< invariance repair rounds (each halves k on failing segments)
};

/// What happened to one subdomain.
struct subdomain_report {
  double area = 0.0;
  std::size_t vertices = 0;  ///< of its delivered mesh
  std::size_t triangles = 0; ///< of its delivered mesh
  double seconds = 0.0;      ///< kernel + check time, summed over runs
  unsigned runs = 0;         ///< 1, or more after invariance repairs
};

/// Statistics of pdd::mesh_subdomains.
struct meshing_statistics {
  /// Interface pieces found split by the kernel (Corollary 13 says 0).
  std::size_t interface_splits = 0;
  /// Subdomain meshings repeated by invariance repairs (0 unless interface_splits > 0).
  std::size_t remeshed_subdomains = 0;
  std::size_t repair_rounds = 0;
  std::vector<subdomain_report> subdomains; ///< by subdomain id

  std::size_t triangles() const noexcept {
    std::size_t n = 0;
    for (const auto& s : subdomains)
      n += s.triangles;
    return n;
  }
};

namespace detail {
inline std::string describe_failures(const std::map<index_t, std::vector<index_t>>& failures,
                                     const decoupled_decomposition& dd) {
  std::string msg;
  for (const auto& [s, edges] : failures)
    for (const index_t e : edges)
      msg += (msg.empty() ? "" : "; ") + std::string("subdomain ") + std::to_string(s) +
             ", separator segment " + std::to_string(dd.path[e].u) + "-" +
             std::to_string(dd.path[e].v) + " (k " + std::to_string(dd.path[e].k) + ")";
  return msg;
}
} // namespace detail

/// Meshes each subdomain's input() with `mesher` under `options.criteria`, concurrently on
/// `executor` (largest expected work, area / max_area, first), and delivers every mesh whose
/// interface pieces are all still edges (Corollary 13; see split_interface_pieces) to
/// `sink.consume(id, mesh)` with triangle markers set to the id; calls sink.start(n) first
/// (when the sink has it) and sink.finish() at the end.
///
/// Invariance repair (never needed when the kernel is Ruppert-type and the decomposition meets
/// the method's preconditions): a subdomain with a split interface piece is not delivered;
/// after the round, every separator segment with a split piece is re-split with k / 2, and the
/// subdomain and its neighbours across those segments are meshed again (neighbours already
/// delivered are delivered again, replacing their mesh), up to options.max_repairs rounds.
/// \tparam M a DelaunayMesher. \tparam E an Executor. \tparam S a MeshSink.
/// \throws pdd::meshing_error(id, ...) for the smallest failing subdomain id when the kernel
/// (or the sink) throws; pdd::decoupling_error naming subdomains and segments when repairs run
/// out. After an exception, finish() has not been called and the sink holds partial results.
/// Complexity: the kernel on every subdomain, plus linear checks.
template <DelaunayMesher M, Executor E, MeshSink S>
meshing_statistics mesh_subdomains(decoupled_decomposition& dd, const meshing_options& options,
                                   const M& mesher, const E& executor, S& sink) {
  const auto m = static_cast<index_t>(dd.num_subdomains());
  meshing_statistics stats;
  stats.subdomains.resize(m);
  std::vector<double> work(m);
  const bool bounded = std::isfinite(options.criteria.max_area) && options.criteria.max_area > 0;
  for (index_t s = 0; s < m; ++s) {
    stats.subdomains[s].area = detail::subdomain_area(dd.parts, s);
    work[s] =
        bounded ? stats.subdomains[s].area / options.criteria.max_area : stats.subdomains[s].area;
  }
  if constexpr (requires { sink.start(m); }) sink.start(m);

  std::mutex mutex;
  std::map<index_t, std::vector<index_t>> failures; // subdomain -> failing path edges
  const auto mesh_one = [&](index_t s) {
    try {
      const auto t0 = std::chrono::steady_clock::now();
      const subdomain_input in = dd.input(s);
      mesher_result r = mesher.mesh(in.domain, options.criteria, uniform_sizing{});
      const std::vector<index_t> split = split_interface_pieces(in, r);
      subdomain_report& rep = stats.subdomains[s];
      rep.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      ++rep.runs;
      if (!split.empty()) {
        std::vector<index_t> edges;
        for (const index_t seg : split)
          edges.push_back(in.segment_path_edge[seg]);
        std::sort(edges.begin(), edges.end());
        edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
        const std::lock_guard lock(mutex);
        stats.interface_splits += split.size();
        failures[s] = std::move(edges);
        return;
      }
      rep.vertices = r.mesh.vertices.size();
      rep.triangles = r.mesh.triangles.size();
      r.mesh.triangle_markers.assign(r.mesh.triangles.size(), static_cast<int>(s));
      sink.consume(s, std::move(r.mesh));
    } catch (const meshing_error& e) {
      if (e.subdomain() == static_cast<long long>(s)) throw;
      throw meshing_error(s, e.what());
    } catch (const std::exception& e) {
      throw meshing_error(s, e.what());
    }
  };
  executor.run(work, mesh_one);

  while (!failures.empty()) {
    if (stats.repair_rounds >= options.max_repairs)
      throw decoupling_error(
          "the decoupling path was split by the kernel and " + std::to_string(options.max_repairs) +
          " repair rounds did not fix it: " + detail::describe_failures(failures, dd));
    ++stats.repair_rounds;
    std::set<index_t> redo;
    std::set<index_t> edges;
    for (const auto& [s, es] : failures) {
      redo.insert(s);
      edges.insert(es.begin(), es.end());
    }
    for (const index_t e : edges) {
      dd.resplit(e, dd.path[e].k / 2.0);
      redo.insert(dd.path[e].sides[0]);
      redo.insert(dd.path[e].sides[1]);
    }
    failures.clear();
    const std::vector<index_t> ids(redo.begin(), redo.end());
    std::vector<double> redo_work(ids.size());
    for (std::size_t j = 0; j < ids.size(); ++j)
      redo_work[j] = work[ids[j]];
    stats.remeshed_subdomains += ids.size();
    executor.run(redo_work, [&](index_t j) { mesh_one(ids[j]); });
  }
  sink.finish();
  return stats;
}

} // namespace pdd
