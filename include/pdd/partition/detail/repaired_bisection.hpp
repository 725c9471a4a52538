/// \file repaired_bisection.hpp
/// Implementation of pdd::connected_bisection: validated vertex weights, the score of a
/// bisection, and the best connected repair of a partitioner's bisection (dissertation 5.1).
#pragma once

#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/errors.hpp>
#include <pdd/partition/bisection_metrics.hpp>
#include <pdd/partition/detail/connected_refine.hpp>
#include <pdd/partition/detail/csr.hpp>
#include <pdd/partition/detail/repair.hpp>

#include <boost/graph/connected_components.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace pdd::detail {

/// Validated vertex weights of g for balancing (all ones when all are zero) and edge checks.
inline std::vector<double> effective_vertex_weights(const partition_graph& g) {
  std::vector<double> w(boost::num_vertices(g));
  double total = 0.0;
  for (std::size_t v = 0; v < w.size(); ++v) {
    check_weight(g[v].weight, "vertex " + std::to_string(v));
    total += w[v] = g[v].weight;
  }
  for (const auto e : boost::make_iterator_range(boost::edges(g)))
    check_weight(g[e].weight, "edge (" + std::to_string(boost::source(e, g)) + ", " +
                                  std::to_string(boost::target(e, g)) + ")");
  if (total == 0.0) w.assign(w.size(), 1.0);
  return w;
}

inline bisection_score score_of(const partition_graph& g, const std::vector<std::uint8_t>& part,
                                const std::vector<double>& weight, const part_limits& limits) {
  std::array<double, 2> pw{0.0, 0.0};
  for (std::size_t v = 0; v < part.size(); ++v)
    pw[part[v]] += weight[v];
  return {balance_excess(pw, limits), cut_weight(g, part)};
}
/// The best connected candidate derived from the disconnected bisection raw (see
/// pdd::connected_bisection). \pre g connected, n >= 2.
inline std::vector<std::uint8_t> repaired_bisection(const partition_graph& g,
                                                    const std::vector<std::uint8_t>& raw,
                                                    const std::vector<double>& weight,
                                                    const part_limits& limits) {
  const std::size_t n = raw.size();
  const auto repaired = [&](std::vector<std::uint8_t> part, std::uint8_t first) {
    part = repair_bisection(g, std::move(part), first, weight);
    connected_refine(g, part, weight, limits, n);
    return part;
  };
  const std::size_t ones = static_cast<std::size_t>(std::count(raw.begin(), raw.end(), 1));
  std::vector<std::vector<std::uint8_t>> candidates;
  if (ones != 0 && ones != n) {
    candidates.push_back(repaired(raw, 0));
    candidates.push_back(repaired(raw, 1));
  }
  for (std::vector<std::uint8_t>& growth : connected_growths(g, weight, limits))
    candidates.push_back(repaired(std::move(growth), 1));
  std::size_t best = 0;
  bisection_score best_score = score_of(g, candidates[0], weight, limits);
  for (std::size_t i = 1; i < candidates.size(); ++i) {
    const bisection_score s = score_of(g, candidates[i], weight, limits);
    if (s < best_score) best = i, best_score = s;
  }
  PDD_ASSERT(is_connected_bisection(g, candidates[best]));
  return candidates[best];
}

} // namespace pdd::detail
