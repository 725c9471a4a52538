/// \file geometric_bound.hpp
/// The per-subdomain numbers of the sizing function built from the geometry (dissertation
/// 8.2, relations 8.9-8.13, Algorithm 8.3): the edge bound e_i from lfs_min(D_i), m_f(D_i) and
/// the small angles of D_i, g_i = 4 sqrt2 e_i^2, and the R2 bound propagated across
/// neighbouring subdomains.
#pragma once

#include <pdd/errors.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <numbers>
#include <queue>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace pdd {

/// Relation 8.9, with the min the text leaves out ("m_i = {a, b}" must be m_i = min{a, b}:
/// 8.3 uses e_i <= m_i <= lfs_min(D_i) and k_i <= e_i): the largest edge length Proposition 20
/// allows in D_i, (1/2) sqrt(m_f(D_i) / sqrt2), held down to lfs_min(D_i).
/// \param area_min m_f(D_i), a true lower bound of the area bound over D_i (infinity: none).
inline double geometric_edge_term(double area_min, double lfs_min) {
  return std::min(0.5 * std::sqrt(area_min / std::numbers::sqrt2), lfs_min);
}

/// e_i of relations 8.10 (small angles theta < 60 deg present in D_i) and 8.11 (none): the
/// shortest Delaunay edge the kernel creates in D_i under f and D_i's own features,
///   e_i = min over theta < 60 deg of min{ [1 + 2 sin(theta/2)] sqrt(2 m_f sin theta) / sqrt3,
///                                        m_i / (cos(theta/2) + sin theta) },
/// e_i = m_i without small angles. Angles >= 60 deg in `angles_rad` are ignored.
/// \throws pdd::sizing_error when area_min or lfs_min is not > 0.
inline double geometric_edge_bound(double area_min, double lfs_min,
                                   std::span<const double> angles_rad = {}) {
  if (!(area_min > 0.0) || !(lfs_min > 0.0))
    throw sizing_error("geometric_edge_bound: m_f(D_i) = " + std::to_string(area_min) +
                       " and lfs_min(D_i) = " + std::to_string(lfs_min) + " must be > 0");
  const double m = geometric_edge_term(area_min, lfs_min);
  double e = m;
  for (const double theta : angles_rad) {
    if (!(theta < std::numbers::pi / 3.0)) continue; // 8.10 is over theta < 60 deg only
    const double s = std::sin(theta), h = std::sin(theta / 2.0);
    const double shielded = (1.0 + 2.0 * h) * std::sqrt(2.0 * area_min * s) / std::numbers::sqrt3;
    e = std::min({e, shielded, m / (std::cos(theta / 2.0) + s)});
  }
  return e;
}

/// Relation 8.13: g_i = 4 sqrt2 e_i^2, the largest m_F(D_i) with k_i = (1/2) sqrt(m_F / sqrt2)
/// <= e_i (relation 8.12).
inline double geometric_area_bound(double edge_bound) {
  return 4.0 * std::numbers::sqrt2 * edge_bound * edge_bound;
}

/// Algorithm 8.3, steps 2-11: lowers g (in place) to the largest values <= g with
/// g_j <= R2 g_i for every neighbour pair (condition (iv)); returns the number of subdomains
/// lowered. `neighbours` lists each pair (i, j) once or twice, in any order.
///
/// The text sorts the subdomains "in decreasing order of g_i" and then scans them "in
/// increasing order" (the scan must be increasing: a small g forces its neighbours down, never
/// the reverse), and after repositioning writes "still we have j < i" for j > i. Its
/// repositioning in a sorted list costs O(N) per change, O(N^2) in all. Here a binary heap
/// keyed by g pops the smallest unsettled value (Dijkstra's order): a popped g_i is final,
/// since every later pop is >= g_i and R2 > 1 makes R2 g >= g, so each neighbour is lowered
/// to R2 g_i at most when g_i is popped. The result is the same fixed point as the text's,
/// g_j = min(g_j, min over i of R2^{hops(i, j)} g_i), in O((N + P) log N) for P pairs.
/// \throws pdd::sizing_error for R2 <= 1, a g that is not > 0, or a pair out of range.
inline std::size_t
propagate_gradation(std::vector<double>& g,
                    std::span<const std::pair<std::size_t, std::size_t>> neighbours, double r2) {
  if (!(r2 > 1.0)) throw sizing_error("propagate_gradation: R2 must be > 1");
  const std::size_t n = g.size();
  for (std::size_t i = 0; i < n; ++i)
    if (!(g[i] > 0.0))
      throw sizing_error("propagate_gradation: g of subdomain " + std::to_string(i) +
                         " is not > 0");
  std::vector<std::vector<std::size_t>> adj(n);
  for (const auto& [a, b] : neighbours) {
    if (a >= n || b >= n)
      throw sizing_error("propagate_gradation: neighbour pair (" + std::to_string(a) + ", " +
                         std::to_string(b) + ") out of range");
    adj[a].push_back(b);
    adj[b].push_back(a);
  }
  const std::vector<double> initial = g;
  using item = std::pair<double, std::size_t>;
  std::priority_queue<item, std::vector<item>, std::greater<>> heap;
  for (std::size_t i = 0; i < n; ++i)
    heap.emplace(g[i], i);
  while (!heap.empty()) {
    const auto [gi, i] = heap.top();
    heap.pop();
    if (gi != g[i]) continue; // a stale entry: g[i] was lowered after it was pushed
    for (const std::size_t j : adj[i])
      if (g[j] > r2 * gi) {
        g[j] = r2 * gi;
        heap.emplace(g[j], j);
      }
  }
  std::size_t lowered = 0;
  for (std::size_t i = 0; i < n; ++i)
    lowered += g[i] < initial[i] ? 1 : 0;
  return lowered;
}

} // namespace pdd
