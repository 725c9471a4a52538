/// \file shielded_domain.hpp
/// pdd::shielded_domain: the result of pdd::shield (shielding/shield.hpp), a domain with its
/// small angles cut off by shield edges.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/shielding/shield_triangle.hpp>

#include <limits>
#include <vector>

namespace pdd {

/// A domain with its small angles shielded: D' = D - T_D (Algorithm 8.2, steps 5-12).
struct shielded_domain {
  /// D': the loops of D with every small-angle apex a replaced by the shield points b', c' and
  /// the shield edge b'c' (marker pdd::shield_marker). Vertices in loop order (the loops of
  /// pdd::find_loops, each walked with the domain on its left); holes and regions copied.
  /// When D has no angle below 60 deg, this is D itself, unchanged.
  pslg domain;
  /// T_D: the shielded triangles, counter-clockwise (apex, b, c).
  std::vector<shield_triangle> triangles;
  /// Per triangle: the index of its shield edge in domain.segments.
  std::vector<index_t> shield_segments;
  /// l of line 5 of Algorithm 8.2 (infinity when there is no small angle).
  double l = std::numeric_limits<double>::infinity();
  /// lfs_min(D) (Definition 7); infinity when there is no small angle (not computed).
  double lfs_min = std::numeric_limits<double>::infinity();
};

} // namespace pdd
