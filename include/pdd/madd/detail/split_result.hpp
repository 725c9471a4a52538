/// \file split_result.hpp
/// Implementation detail of MADD: the options and the result of one 2-way split of a region
/// (split.hpp, chord_split.hpp).
#pragma once

#include <pdd/madd/detail/graph.hpp>
#include <pdd/madd/detail/quotas.hpp>
#include <pdd/madd/detail/region.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace pdd::detail {

/// Options of one split.
struct madd_split_options {
  madd_graph_options graph;
  double target_length = 1.0; ///< h at refinement level 0
  int max_levels = 8;         ///< levels h, h/2, h/4, ...
  int extra_levels = 2;       ///< levels tried after a first valid but unbalanced split
  int max_encroachment_depth = 8;
  double imbalance_bound = 0.75;   ///< L_b: the largest split_balance accepted at once
  double max_part_fraction = 0.52; ///< given to the partitioner
  /// Into N, the subdomains the region is to become (quotas.hpp); 0 otherwise (halves).
  std::size_t quota = 0;
  int max_repairs = 64;
  std::uint64_t seed = 1;
  double feature_clearance = 0.0; ///< madd_options::feature_clearance
};

/// The result of one split.
struct madd_split_result {
  bool ok = false;
  std::array<madd_region, 2> children;
  std::vector<madd_edge_split> kept; ///< refinement vertices that separators end at
  int level = -1;
  double separator_length = 0.0;
  double min_angle = 180.0;  ///< smallest angle the separator forms (degrees)
  double max_fraction = 1.0; ///< split_balance (for quota 2: largest child area / region area)
  std::size_t z_points = 0;  ///< |Z| at the level used
  std::size_t junctions = 0;
  std::size_t graph_nodes = 0;
  std::size_t repairs = 0;
  std::size_t smoothing_moves = 0;
  std::size_t levels_tried = 0;
  bool fallback = false; ///< algorithm 1 found nothing, algorithm 2 split the region
  bool chord = false;    ///< no medial-axis separator: a straight chord split it (chord_split.hpp)
  std::string failure;   ///< why there is no split (when !ok)
};

/// How far above the partitioner's bound the balance of a last split may be before finer
/// refinement levels are tried too (the best split kept).
inline constexpr double last_split_margin = 0.05;

/// A graph of fewer nodes is coarse: a finer level may balance a last split better; a finer
/// level of a larger graph mostly costs time (a region of long fjords: 14x at N = 4096).
inline constexpr std::size_t coarse_graph_nodes = 64;

/// Whether a split is one of the last of a region (into N, a quota of at most 8).
inline bool is_last_split(const madd_split_options& o) {
  return o.quota >= 2 && o.quota <= 8;
}

/// The largest balance a split takes at once: L_b, but for a last split (its children are, or
/// are soon split into, final subdomains; quotas.hpp) the partitioner's bound plus
/// last_split_margin. A region with few cells at its first level (4-9
/// at N = 4096 on Lake Superior) cannot be cut closer than a cell, and with L_b (0.75) its
/// larger child set the largest subdomain (largest/mean up to 1.68). Earlier splits need not
/// be tight: the next round's quotas follow the areas their children got.
inline double accepted_balance(const madd_split_options& o) {
  if (is_last_split(o)) return std::min(o.imbalance_bound, o.max_part_fraction + last_split_margin);
  return o.imbalance_bound;
}

} // namespace pdd::detail
