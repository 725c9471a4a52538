/// \file decoupling_parameter.hpp
/// The decoupling parameter k of the uniform method (dissertation eq. 6.1, Proposition 12,
/// Lemma 14, Theorem 15).
#pragma once

#include <pdd/core/mesh_criteria.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace pdd {

/// The area term of Theorem 15: (1/2) sqrt(A / B'), with A = criteria.max_area and
/// B' = max(B, sqrt 2) for the criteria's ratio bound B. Lemma 14: a triangle of area > A and
/// ratio <= B has its shortest edge l > sqrt(A / B) (A < r l <= B l^2), so area splits never make
/// an edge shorter than half of that. For the dissertation's B = sqrt 2 this is its
/// (1/2) sqrt(A / sqrt 2); B < sqrt 2 (angles above 20.7 deg) is outside Ruppert's guarantee, and
/// then the sqrt 2 value, the smaller of the two, is used. Infinity when A is infinite.
/// Complexity O(1).
inline double decoupling_area_term(const mesh_criteria& criteria) {
  if (!std::isfinite(criteria.max_area)) return std::numeric_limits<double>::infinity();
  const double b = std::max(criteria.ratio_bound(), std::numbers::sqrt2);
  return 0.5 * std::sqrt(criteria.max_area / b);
}

/// The decoupling parameter k = min(lfs_min(D_H), L / 4, (1/2) sqrt(A / sqrt 2)) of Theorem 15
/// (without an area bound, Proposition 12: k = min(lfs_min(D_H), L / 4)), where L is the length
/// of the shortest separator segment. Splitting every separator segment by Lemma 9 with this k
/// gives a decoupling path: Ruppert-type refinement of each subdomain never splits it.
/// \pre lfs_min > 0, shortest_separator > 0 (infinity: no separators).
/// Complexity O(1).
inline double decoupling_parameter(double lfs_min, double shortest_separator,
                                   const mesh_criteria& criteria) {
  return std::min({lfs_min, shortest_separator / 4.0, decoupling_area_term(criteria)});
}

} // namespace pdd
