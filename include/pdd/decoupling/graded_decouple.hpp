/// \file graded_decouple.hpp
/// pdd::decouple_graded: the graded Delaunay decoupling path (dissertation 7.4-7.5,
/// Propositions 20-21, Theorem 22): one k_i per subdomain from its own area bound m(D_i).
#pragma once

#include <pdd/concepts/executor.hpp>
#include <pdd/core/decomposition.hpp>
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/decoupling/decouple.hpp>
#include <pdd/decoupling/decoupled_decomposition.hpp>
#include <pdd/decoupling/decoupling_parameter.hpp>
#include <pdd/decoupling/detail/build.hpp>
#include <pdd/decoupling/interface_split.hpp>
#include <pdd/errors.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <queue>
#include <string>
#include <utility>
#include <vector>

namespace pdd {

/// The graded decoupling path and its parameters.
struct graded_decoupling {
  /// The decomposition with its decoupling path: each path edge split with the smaller k_i of
  /// its two sides; path.k the smallest k_i.
  decoupled_decomposition path;
  /// k_i = min(lfs_min(D_i), sqrt 3 L_i / 4, (1/2) sqrt(m(D_i) / sqrt 2)) per subdomain
  /// (Proposition 20 with Theorem 15's terms, pdd::separator_term; L_i the shortest separator
  /// segment of D_i).
  std::vector<double> subdomain_k;
  /// max over interfaces of k_j / k_i (k_i <= k_j); relation 7.1 needs it below sqrt 3.
  double k_ratio_max = 1.0;
  /// Subdomains whose k_i was lowered so that relation 7.1 holds (graded_decoupling_options::
  /// lower_k).
  std::size_t lowered_k = 0;
};

/// Options of pdd::decouple_graded.
struct graded_decoupling_options {
  /// Where relation 7.1 fails on a separator segment E between D_i and D_j (k_i <= k_j),
  /// true: lower k_j to sqrt 3 |E| / (2 nu), nu the piece count of E for k_i, so that the
  /// pieces meet Proposition 20 on both sides, and propagate (see pdd::decouple_graded);
  /// false: throw pdd::decoupling_error.
  bool lower_k = true;
};

namespace detail {
/// The largest k_j that relation 7.1 allows beside k_i on a segment of length `length`:
/// sqrt 3 |E| / (2 nu(k_i)), nu(k_i) = interface_split_count (shrunk by a relative 1e-13
/// so that the check |E| / nu >= 2 k_j / sqrt 3 holds in floating point). Nondecreasing in k_i,
/// and > k_i when k_i <= separator_term(|E|) (pieces of length >= 2 k_i / sqrt 3, with
/// separator_term's margin).
inline double largest_k_beside(double length, double k_i) {
  const double nu = static_cast<double>(interface_split_count(length, k_i));
  return (length / nu) * (std::numbers::sqrt3 / 2.0) * (1.0 - 1e-13);
}

/// Lowers k (in place) to the largest values <= k with k_j <= largest_k_beside(|E|, k_i) on
/// every segment E between D_i and D_j with k_i <= k_j: Dijkstra's order (smallest k first;
/// a popped k is final since largest_k_beside(|E|, x) > x and is nondecreasing in x).
/// Returns the number of subdomains lowered. Complexity O((m + |path|) log m).
inline std::size_t lower_k_for_relation_7_1(const std::vector<path_edge>& path,
                                            std::vector<double>& k) {
  std::vector<std::vector<std::pair<index_t, double>>> adj(k.size());
  for (const path_edge& e : path) {
    adj[e.sides[0]].emplace_back(e.sides[1], e.length);
    adj[e.sides[1]].emplace_back(e.sides[0], e.length);
  }
  const std::vector<double> initial = k;
  using item = std::pair<double, index_t>;
  std::priority_queue<item, std::vector<item>, std::greater<>> heap;
  for (index_t s = 0; s < k.size(); ++s)
    heap.emplace(k[s], s);
  while (!heap.empty()) {
    const auto [ks, s] = heap.top();
    heap.pop();
    if (ks != k[s]) continue;
    for (const auto& [t, length] : adj[s]) {
      if (!(k[t] > ks)) continue;
      const double allowed = largest_k_beside(length, ks);
      if (k[t] > allowed) {
        k[t] = allowed;
        heap.emplace(allowed, t);
      }
    }
  }
  std::size_t lowered = 0;
  for (std::size_t s = 0; s < k.size(); ++s)
    lowered += k[s] < initial[s] ? 1 : 0;
  return lowered;
}

/// The per-subdomain values of the graded path: k_i, lfs_min(D_i), the shortest separator
/// segment L_i of D_i, and how many k_i relation 7.1 lowered.
struct graded_k_values {
  std::vector<double> k, lfs, shortest;
  std::size_t lowered = 0;
};

/// k_i = decoupling_parameter(lfs_min(D_i), L_i, criteria with max_area min(criteria.max_area,
/// area_lower_bound[i])) for every subdomain of d (path: its separator segments), lowered for
/// relation 7.1 when `lower` (lower_k_for_relation_7_1). Complexity: lfs_min per subdomain on
/// the executor, plus O((m + |path|) log m).
template <Executor E>
graded_k_values compute_graded_k(const decomposition& d, const std::vector<path_edge>& path,
                                 const mesh_criteria& criteria,
                                 const std::vector<double>& area_lower_bound, const E& executor,
                                 bool lower) {
  const std::size_t m = d.subdomains.size();
  graded_k_values v;
  v.shortest.assign(m, std::numeric_limits<double>::infinity());
  for (const path_edge& e : path)
    for (const index_t s : e.sides)
      v.shortest[s] = std::min(v.shortest[s], e.length);
  v.lfs = subdomain_lfs(d, executor);
  v.k.resize(m);
  for (std::size_t s = 0; s < m; ++s) {
    mesh_criteria c = criteria;
    c.max_area = std::min(criteria.max_area, area_lower_bound[s]);
    v.k[s] = decoupling_parameter(v.lfs[s], v.shortest[s], c);
  }
  if (lower) v.lowered = lower_k_for_relation_7_1(path, v.k);
  return v;
}

/// Throws pdd::decoupling_error unless there is one area bound per subdomain of d.
inline void check_area_bounds(const decomposition& d, const std::vector<double>& bounds,
                              const char* what) {
  if (bounds.size() != d.subdomains.size())
    throw decoupling_error(std::string(what) + ": " + std::to_string(bounds.size()) +
                           " area bounds for " + std::to_string(d.subdomains.size()) +
                           " subdomains");
}
} // namespace detail

/// The graded decoupling parameters k_i of decomposition d as pdd::decouple_graded computes
/// them (Proposition 20 with Theorem 15's terms, lowered where relation 7.1 needs it when
/// o.lower_k), without building the path. The pipeline caps the graded shields' l_i with them
/// (pdd::shield_graded_decomposition): shielding comes before the path, on the decomposition.
/// \param area_lower_bound as for pdd::decouple_graded.
/// 	hrows pdd::decoupling_error for a malformed decomposition or a wrong number of bounds;
/// pdd::geometry_error from lfs_min. Complexity: lfs_min per subdomain on the executor, plus
/// O((m + |path|) log m). Thread-safety: reentrant.
template <Executor E = sequential_executor>
std::vector<double> graded_subdomain_k(const decomposition& d, const mesh_criteria& criteria,
                                       const std::vector<double>& area_lower_bound,
                                       const E& executor = {},
                                       const graded_decoupling_options& o = {}) {
  detail::check_decomposition(d);
  detail::check_area_bounds(d, area_lower_bound, "graded_subdomain_k");
  std::vector<path_edge> path;
  std::vector<std::vector<index_t>> loop_edge_path;
  detail::collect_path_edges(d, path, loop_edge_path);
  return detail::compute_graded_k(d, path, criteria, area_lower_bound, executor, o.lower_k).k;
}

/// Refines the separators of d into a graded decoupling path: every separator segment E
/// between D_i and D_j (k_i <= k_j) is split into the smallest nu with |E| / nu < 2 k_i
/// (Lemma 9 with k_i), and relation 7.1 is checked: |E| / nu >= 2 k_j / sqrt 3, i.e. some nu
/// with |E| / (2 k_i) < nu <= sqrt 3 |E| / (2 k_j) exists (Theorem 22). The pieces then meet
/// Proposition 20 on both sides, so Ruppert-type refinement of each subdomain with area
/// bounds >= m(D_i) never splits them (Proposition 21).
/// Where relation 7.1 fails (k_j / k_i too large: a decomposition that does not meet
/// Condition 2, or k held down by lfs_min or a short separator on one side), o.lower_k lowers
/// k_j to the largest value the relation allows, propagated through the neighbours (smallest
/// k first). That is safe: k_i enters Proposition 20 only as a lower bound (Theorem 19: A is
/// any constant below the area bound, and k <= lfs_min, sqrt 3 L / 4 still hold for a smaller k),
/// so the kernel still meshes D_j with the field itself; the cost is shorter pieces on D_j's
/// separators (graded_decoupling::lowered_k counts the subdomains).
/// \param area_lower_bound per subdomain, a TRUE lower bound m(D_i) of the area bound over it
/// (pdd::sizing_range; infinity: unbounded), already combined with criteria.max_area.
/// \throws pdd::decoupling_error naming the interface (subdomains, k_i, k_j, length) where
/// relation 7.1 fails (the subdomains need a finer decomposition, Algorithm 7.1), or as
/// pdd::decouple. Complexity: as pdd::decouple. Thread-safety: reentrant.
template <Executor E = sequential_executor>
graded_decoupling decouple_graded(decomposition d, const mesh_criteria& criteria,
                                  const std::vector<double>& area_lower_bound,
                                  const E& executor = {}, const graded_decoupling_options& o = {}) {
  detail::check_decomposition(d);
  detail::check_area_bounds(d, area_lower_bound, "decouple_graded");
  graded_decoupling g;
  decoupled_decomposition& dd = g.path;
  detail::collect_path_edges(d, dd.path, dd.loop_edge_path);
  detail::graded_k_values kv =
      detail::compute_graded_k(d, dd.path, criteria, area_lower_bound, executor, o.lower_k);
  g.subdomain_k = std::move(kv.k);
  g.lowered_k = kv.lowered;
  const std::vector<double>& lfs = kv.lfs;
  const std::vector<double>& shortest = kv.shortest;
  dd.lfs_min = *std::min_element(lfs.begin(), lfs.end());
  dd.shortest_separator = *std::min_element(shortest.begin(), shortest.end());
  dd.k = *std::min_element(g.subdomain_k.begin(), g.subdomain_k.end());
  dd.area_term = decoupling_area_term(criteria);
  dd.parts = std::move(d);
  for (path_edge& e : dd.path) {
    const double ki = std::min(g.subdomain_k[e.sides[0]], g.subdomain_k[e.sides[1]]);
    const double kj = std::max(g.subdomain_k[e.sides[0]], g.subdomain_k[e.sides[1]]);
    e.k = ki;
    e.pieces = interface_split_count(e.length, ki);
    g.k_ratio_max = std::max(g.k_ratio_max, kj / ki);
    if (e.length / e.pieces < 2.0 * kj / std::numbers::sqrt3)
      throw decoupling_error(
          "relation 7.1 fails on the separator segment " + std::to_string(e.u) + "-" +
          std::to_string(e.v) + " between subdomains " + std::to_string(e.sides[0]) + " and " +
          std::to_string(e.sides[1]) + " (length " + std::to_string(e.length) + ", k " +
          std::to_string(ki) + " and " + std::to_string(kj) +
          "): no piece count meets Theorem 22; the subdomains need a finer decomposition");
  }
  detail::place_split_points(dd);
  return g;
}

} // namespace pdd
