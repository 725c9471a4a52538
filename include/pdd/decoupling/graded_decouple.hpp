/// \file graded_decouple.hpp
/// pdd::decouple_graded: the graded Delaunay decoupling path (dissertation 7.4-7.5,
/// Propositions 20-21, Theorem 22): one k_i per subdomain from its own area bound m(D_i).
#pragma once

#include <pdd/concepts/executor.hpp>
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/decoupling/decouple.hpp>
#include <pdd/decoupling/decoupled_decomposition.hpp>
#include <pdd/decoupling/decoupling_parameter.hpp>
#include <pdd/decoupling/detail/build.hpp>
#include <pdd/decoupling/interface_split.hpp>
#include <pdd/errors.hpp>
#include <pdd/madd/decomposition.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace pdd {

/// The graded decoupling path and its parameters.
struct graded_decoupling {
  decoupled_decomposition path;
  /// k_i = min(lfs_min(D_i), L_i / 4, (1/2) sqrt(m(D_i) / sqrt 2)) per subdomain
  /// (Proposition 20 with Theorem 15's terms; L_i the shortest separator segment of D_i).
  std::vector<double> subdomain_k;
  /// max over interfaces of k_j / k_i (k_i <= k_j); relation 7.1 needs it below sqrt 3.
  double k_ratio_max = 1.0;
};

/// Refines the separators of d into a graded decoupling path: every separator segment E
/// between D_i and D_j (k_i <= k_j) is split into the smallest nu with |E| / nu < 2 k_i
/// (Lemma 9 with k_i), and relation 7.1 is checked: |E| / nu >= 2 k_j / sqrt 3, i.e. some nu
/// with |E| / (2 k_i) < nu <= sqrt 3 |E| / (2 k_j) exists (Theorem 22). The pieces then meet
/// Proposition 20 on both sides, so Ruppert-type refinement of each subdomain with area
/// bounds >= m(D_i) never splits them (Proposition 21).
/// \param area_lower_bound per subdomain, a TRUE lower bound m(D_i) of the area bound over it
/// (pdd::sizing_range; infinity: unbounded), already combined with criteria.max_area.
/// \throws pdd::decoupling_error naming the interface (subdomains, k_i, k_j, length) where
/// relation 7.1 fails (the subdomains need a finer decomposition, Algorithm 7.1), or as
/// pdd::decouple. Complexity: as pdd::decouple. Thread-safety: reentrant.
template <Executor E = sequential_executor>
graded_decoupling decouple_graded(decomposition d, const mesh_criteria& criteria,
                                  const std::vector<double>& area_lower_bound,
                                  const E& executor = {}) {
  detail::check_decomposition(d);
  const std::size_t m = d.subdomains.size();
  if (area_lower_bound.size() != m)
    throw decoupling_error("decouple_graded: " + std::to_string(area_lower_bound.size()) +
                           " area bounds for " + std::to_string(m) + " subdomains");
  graded_decoupling g;
  decoupled_decomposition& dd = g.path;
  detail::collect_path_edges(d, dd.path, dd.loop_edge_path);
  std::vector<double> shortest(m, std::numeric_limits<double>::infinity());
  for (const path_edge& e : dd.path)
    for (const index_t s : e.sides)
      shortest[s] = std::min(shortest[s], e.length);
  const std::vector<double> lfs = detail::subdomain_lfs(d, executor);
  g.subdomain_k.resize(m);
  for (std::size_t s = 0; s < m; ++s) {
    mesh_criteria c = criteria;
    c.max_area = std::min(criteria.max_area, area_lower_bound[s]);
    g.subdomain_k[s] = decoupling_parameter(lfs[s], shortest[s], c);
  }
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
