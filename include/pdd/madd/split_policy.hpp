/// \file split_policy.hpp
/// pdd::madd_split_policy: which leaves of MADD's split tree are split, and in which order,
/// for graded decompositions (dissertation 4.4: density weights or area-bound ratios; 7.3,
/// Algorithm 7.1: the non-acceptable subdomains of conditions 1-3).
#pragma once

#include <pdd/core/point.hpp>

#include <functional>
#include <span>
#include <vector>

namespace pdd {

/// A leaf of MADD's split tree as a split policy sees it: its loops as points (loops[0] the
/// outer loop, counter-clockwise; loops[1..] the holes, clockwise) and its area. Two leaves
/// that share an edge store bitwise-identical endpoints, so neighbours are found from their
/// shared edges; the view is valid only during the call.
struct madd_leaf_view {
  /// The leaf's loops as points: loops[0] the outer loop (counter-clockwise), loops[1..] the
  /// holes (clockwise); each span valid only during the call.
  std::vector<std::span<const point>> loops;
  /// The leaf's area (outer loop less its holes), in squared input units.
  double area = 0.0;
  /// MADD never splits this leaf, whatever its priority: a cap around a small angle between
  /// the faces of a general PSLG, meshed whole by the kernel.
  bool keep_whole = false;
};

/// Decides the splits of a graded MADD (4.4, 7.3). Called before every round with all
/// current leaves (in the decomposition's order); returns one priority per leaf: a leaf with
/// priority > 0 must be split, the highest first (a round splits those within
/// madd_options::round_fraction of the highest, as the area does for the uniform MADD);
/// priority <= 0: the leaf is acceptable as it is. The policy must be a pure function of the
/// leaves (the result of pdd::decompose stays bitwise identical for every thread count) and is
/// called from one thread at a time, inside pdd::decompose's task arena (so work it runs in
/// parallel there, like Algorithm 7.1's measuring of new leaves, uses madd_options::threads).
using madd_split_policy = std::function<std::vector<double>(std::span<const madd_leaf_view>)>;

} // namespace pdd
