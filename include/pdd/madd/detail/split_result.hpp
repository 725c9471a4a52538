/// \file split_result.hpp
/// Implementation detail of MADD: the options and the result of one 2-way split of a region
/// (split.hpp, chord_split.hpp).
#pragma once

#include <pdd/madd/detail/graph.hpp>
#include <pdd/madd/detail/region.hpp>

#include <array>
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
  double imbalance_bound = 0.75;   ///< L_b: largest child area / region area accepted at once
  double max_part_fraction = 0.55; ///< given to the partitioner
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
  double max_fraction = 1.0; ///< largest child area / region area
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

} // namespace pdd::detail
