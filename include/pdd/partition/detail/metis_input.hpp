/// \file metis_input.hpp
/// Implementation detail of pdd::metis_partitioner: the CSR arrays METIS reads, with the real
/// weights scaled to integers that cannot overflow METIS's index type. Independent of metis.h
/// (templated on the index type) so that it is tested on every build.
#pragma once

#include <pdd/partition/detail/csr.hpp>
#include <pdd/errors.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace pdd::detail {

/// METIS's graph arrays: xadj/adjncy/adjwgt (both directions of each edge) and vwgt.
template <class Idx>
struct metis_input {
  std::vector<Idx> xadj, adjncy, adjwgt, vwgt;
};

/// Budget for each total (vertex weights; edge weights counted once per edge): METIS sums
/// weights in Idx (part weights, cuts, arc sums per vertex), so each total stays below
/// 2^29 + (count of items), leaving headroom below 2^31 for sums of both arc directions.
inline constexpr double metis_weight_budget = 536870912.0; // 2^29

/// Scales weights w_i >= 0 with positive total to integers: round(w_i * budget / total), at
/// least 1 for every positive w_i (and for every w_i when zero_to_one), 0 otherwise. The
/// integers add up to at most budget + count.
template <class Idx>
Idx scaled_weight(double w, double scale, bool zero_to_one) {
  if (w == 0.0 && !zero_to_one) return 0;
  return static_cast<Idx>(std::max(1.0, std::round(w * scale)));
}

/// METIS arrays of g (zero edge weights become 1, since METIS requires positive edge weights).
/// \throws limit_error when the graph is too large for Idx with this headroom.
template <class Idx>
metis_input<Idx> to_metis_input(const ml_graph& g) {
  const std::size_t n = boost::num_vertices(g), arcs = boost::num_edges(g);
  const double idx_max = static_cast<double>(std::numeric_limits<Idx>::max());
  if (static_cast<double>(n) + 1.0 > metis_weight_budget ||
      2.0 * static_cast<double>(arcs) > metis_weight_budget)
    throw limit_error("metis_partitioner: graph with " + std::to_string(n) + " vertices and " +
                      std::to_string(arcs / 2) + " edges exceeds METIS's index range");
  PDD_ASSERT(3.0 * metis_weight_budget < idx_max);
  double vtotal = 0.0, etotal = 0.0;
  for (std::size_t v = 0; v < n; ++v)
    vtotal += g[v].weight;
  for (const auto e : boost::make_iterator_range(boost::edges(g)))
    if (boost::source(e, g) < boost::target(e, g)) etotal += g[e].weight;
  const double vscale = vtotal > 0.0 ? metis_weight_budget / vtotal : 1.0;
  const double escale = etotal > 0.0 ? metis_weight_budget / etotal : 1.0;
  metis_input<Idx> in;
  in.xadj.reserve(n + 1);
  in.adjncy.reserve(arcs);
  in.adjwgt.reserve(arcs);
  in.vwgt.reserve(n);
  in.xadj.push_back(0);
  for (std::size_t v = 0; v < n; ++v) {
    in.vwgt.push_back(scaled_weight<Idx>(g[v].weight, vscale, false));
    for (const auto e : boost::make_iterator_range(boost::out_edges(v, g))) {
      in.adjncy.push_back(static_cast<Idx>(boost::target(e, g)));
      in.adjwgt.push_back(scaled_weight<Idx>(g[e].weight, escale, true));
    }
    in.xadj.push_back(static_cast<Idx>(in.adjncy.size()));
  }
  return in;
}

} // namespace pdd::detail
