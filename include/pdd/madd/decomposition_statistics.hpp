/// \file decomposition_statistics.hpp
/// pdd::decomposition_statistics: the measurements of one MADD decomposition (dissertation
/// 5.2's quantities plus the work counters of the splits).
#pragma once

#include <cstddef>
#include <vector>

namespace pdd {

/// Measurements of one decomposition (dissertation 5.2's quantities).
struct decomposition_statistics {
  /// N, the number of subdomains made.
  std::size_t subdomains = 0;
  /// Smallest angle formed by a separator with the boundary or with another separator
  /// (degrees; 180 when there is no separator).
  double min_separator_angle_deg = 180.0;
  /// Total length of the separators (every interface edge once), in input units.
  double separator_length_total = 0.0;
  /// Per subdomain: the length of its interface edges.
  std::vector<double> separator_length_per_subdomain;
  /// Largest subdomain area over the mean subdomain area (1: perfectly balanced; 0 when the
  /// mean is 0).
  double max_area_over_mean = 0.0;
  /// Smallest subdomain area over the mean subdomain area (0 when the mean is 0).
  double min_area_over_mean = 0.0;
  /// Shortest interface edge divided by sqrt(mean subdomain area) (the "small segments" of
  /// 4.2; 0 when there is no interface).
  double min_interface_edge_rel = 0.0;
  /// Wall-clock seconds of the decomposition (pdd::decompose, the splits and the assembly).
  double time_s = 0.0;
  std::size_t splits = 0;          ///< successful 2-way splits
  std::size_t rounds = 0;          ///< rounds of concurrent splits
  std::size_t failed_splits = 0;   ///< subdomains found unsplittable
  std::size_t repairs = 0;         ///< repartitions (5.1)
  std::size_t smoothing_moves = 0; ///< nodes moved by the local search (4.2)
  std::size_t boundary_points = 0; ///< |Z| summed over the successful splits
  std::size_t levels_tried = 0;    ///< refinement levels tried, summed over all splits
  /// Splits where algorithm 1 found no separator at any level and algorithm 2 was used
  /// (exactly symmetric boundaries have no junction triangles).
  std::size_t algorithm_fallbacks = 0;
  /// Splits of a region with features (a general PSLG) where no medial-axis separator cleared
  /// the features and a straight chord beside them was used.
  std::size_t chord_splits = 0;
  /// The balance of a split: for a region split in two halves, larger child area / parent
  /// area; for one that is to become q subdomains (into N), the larger area per subdomain of
  /// the children over the parent's, halved. Mean over the splits.
  double mean_split_fraction = 0.0;
  /// The maximum over the splits of the balance above (0.5: an even split; 0 when there was
  /// no split).
  double max_split_fraction = 0.0;
  /// splits_per_level[l]: successful splits that used refinement level l (r 2^l).
  std::vector<std::size_t> splits_per_level;
};

} // namespace pdd
