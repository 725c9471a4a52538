/// \file multilevel.hpp
/// Implementation detail of pdd::boost_partitioner: the multilevel bisection driver (coarsen by
/// heavy-edge matching, bisect the coarsest graph, project back with FM refinement per level).
#pragma once

#include <pdd/partition/detail/coarsen.hpp>
#include <pdd/partition/detail/csr.hpp>
#include <pdd/partition/detail/exact.hpp>
#include <pdd/partition/detail/fm.hpp>
#include <pdd/partition/detail/initial.hpp>

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace pdd::detail {

/// Tuning of the multilevel bisection (see pdd::boost_partitioner).
struct multilevel_parameters {
  std::size_t coarsen_to = 20;
  int initial_tries = 8;
  int refinement_passes = 8;
  int trials = 3;
};

/// One multilevel V-cycle with the generator rng. \pre num_vertices(g) >= 2.
inline std::vector<std::uint8_t> multilevel_v_cycle(const ml_graph& g, const part_limits& limits,
                                                    const multilevel_parameters& p,
                                                    std::mt19937_64& rng) {
  const double max_vertex_weight = 1.5 * total_vertex_weight(g) / static_cast<double>(p.coarsen_to);
  std::vector<coarse_level> levels;
  const ml_graph* current = &g;
  while (boost::num_vertices(*current) > p.coarsen_to) {
    const std::size_t n = boost::num_vertices(*current);
    coarse_level level = contract(*current, heavy_edge_matching(*current, rng, max_vertex_weight));
    const bool stalled = boost::num_vertices(level.graph) * 20 > n * 19; // < 5% smaller
    levels.push_back(std::move(level));
    current = &levels.back().graph;
    if (stalled) break;
  }
  std::vector<std::uint8_t> part =
      initial_bisection(*current, limits, p.initial_tries, p.refinement_passes, rng);
  for (std::size_t i = levels.size(); i-- > 0;) {
    const ml_graph& fine = i == 0 ? g : levels[i - 1].graph;
    std::vector<std::uint8_t> projected(boost::num_vertices(fine));
    for (std::size_t v = 0; v < projected.size(); ++v)
      projected[v] = part[levels[i].fine_to_coarse[v]];
    part = std::move(projected);
    fm_refine(fine, part, limits, p.refinement_passes);
  }
  return part;
}

/// The best of p.trials V-cycles, each with its own generator seeded from (seed, trial); graphs
/// of at most exact_bisection_max_vertices are solved exactly. Deterministic in (g, seed).
inline std::vector<std::uint8_t> multilevel_bisection(const ml_graph& g, const part_limits& limits,
                                                      const multilevel_parameters& p,
                                                      std::uint64_t seed) {
  if (boost::num_vertices(g) <= exact_bisection_max_vertices) return exact_bisection(g, limits);
  std::vector<std::uint8_t> best;
  bisection_score best_score{};
  for (int trial = 0; trial < p.trials; ++trial) {
    std::mt19937_64 rng(mix_seed(seed, static_cast<std::uint64_t>(trial)));
    std::vector<std::uint8_t> part = multilevel_v_cycle(g, limits, p, rng);
    const bisection_score s = score_bisection(g, part, limits);
    if (best.empty() || s < best_score) {
      best = std::move(part);
      best_score = s;
    }
  }
  return best;
}

} // namespace pdd::detail
