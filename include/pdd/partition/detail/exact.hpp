/// \file exact.hpp
/// Implementation detail of the partitioners: the exact bisection of a small graph by
/// enumeration. Multilevel partitioners (METIS included) are unreliable on a handful of
/// vertices; below exact_bisection_max_vertices the optimum is cheap to enumerate.
#pragma once

#include <pdd/partition/detail/csr.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pdd::detail {

/// Largest vertex count solved by enumeration (2^(n-1) bisections, ~2 ms at n = 12).
inline constexpr std::size_t exact_bisection_max_vertices = 12;

/// The bisection with the smallest score (excess over the parts' limits, then cut) among all
/// with two non-empty parts; ties go to the first in enumeration order, where vertex 0 is in
/// part 0 (with equal limits it always is; with unequal ones each bisection is also scored with
/// its parts swapped).
/// n = 0 gives {} and n = 1 gives {0}.
/// \pre num_vertices(g) <= exact_bisection_max_vertices. Complexity O(2^n n).
inline std::vector<std::uint8_t> exact_bisection(const ml_graph& g, const part_limits& limits) {
  const std::size_t n = boost::num_vertices(g);
  PDD_ASSERT(n <= exact_bisection_max_vertices);
  if (n < 2) return std::vector<std::uint8_t>(n, 0);
  // Dense matrix of arc weights (0 where no edge).
  std::vector<double> wmat(n * n, 0.0);
  for (const auto e : boost::make_iterator_range(boost::edges(g)))
    wmat[boost::source(e, g) * n + boost::target(e, g)] = g[e].weight;
  const double total = total_vertex_weight(g);
  std::uint32_t best_mask = 0;
  bool best_swapped = false;
  bisection_score best{};
  for (std::uint32_t half = 1; half < (1U << (n - 1)); ++half) {
    const std::uint32_t mask = half << 1; // bit v set: vertex v in part 1
    double w1 = 0.0, cut = 0.0;
    for (std::size_t v = 1; v < n; ++v) {
      if (!(mask >> v & 1U)) continue;
      w1 += g[v].weight;
      for (std::size_t u = 0; u < n; ++u)
        if (!(mask >> u & 1U)) cut += wmat[v * n + u];
    }
    const bisection_score s{balance_excess({total - w1, w1}, limits), cut};
    if (best_mask == 0 || s < best) best = s, best_mask = mask, best_swapped = false;
    if (limits[0] == limits[1]) continue;
    const bisection_score swapped{balance_excess({w1, total - w1}, limits), cut};
    if (swapped < best) best = swapped, best_mask = mask, best_swapped = true;
  }
  std::vector<std::uint8_t> part(n);
  for (std::size_t v = 0; v < n; ++v)
    part[v] = static_cast<std::uint8_t>((best_mask >> v & 1U) ^ (best_swapped ? 1U : 0U));
  return part;
}

} // namespace pdd::detail
