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

/// The separator term of the decoupling parameter: the largest k for which Lemma 9's pieces
/// of every separator segment at least `shortest_separator` long lie in [2k / sqrt 3, 2k).
/// Equation 6.1 takes L / 4: with l >= 4k, Lemma 9's nu >= 3 and 2 (nu - 1) k / nu >= 4k / 3.
/// That is sufficient, not necessary: interface_split_count gives nu = 2 pieces of length l / 2
/// for 2k <= l < 4k, and l / 2 >= 2k / sqrt 3 holds for l >= 4k / sqrt 3, so k <= sqrt 3 L / 4
/// (about 1.73 times L / 4) keeps every piece in the interval; nu = 1 (l < 2k) cannot occur then.
/// Lemmas 10 and 11 use only the interval and the angles >= Phi0, not nu >= 3, so the proofs of
/// Theorems 15 and 22 stand. A relative margin of 1e-9 keeps l / 2 >= 2k / sqrt 3 in floating
/// point (decouple_graded checks it exactly as written). On the Bahamas at 5M triangles (4096
/// subdomains) the short segments MADD leaves between two junctions set k in hundreds of
/// subdomains; L / 4 made 155K split points, this term 131K.
inline double separator_term(double shortest_separator) noexcept {
  return shortest_separator * (std::numbers::sqrt3 / 4.0) * (1.0 - 1e-9);
}

/// The decoupling parameter k = min(lfs_min(D_H), sqrt 3 L / 4, (1/2) sqrt(A / sqrt 2)):
/// Theorem 15 (without an area bound, Proposition 12), where L is the length of the shortest
/// separator segment, with separator_term's sqrt 3 L / 4 in place of the text's L / 4 (see
/// there). Splitting every separator segment by Lemma 9 with this k gives a decoupling path:
/// Ruppert-type refinement of each subdomain never splits it.
/// \pre lfs_min > 0, shortest_separator > 0 (infinity: no separators).
/// Complexity O(1).
inline double decoupling_parameter(double lfs_min, double shortest_separator,
                                   const mesh_criteria& criteria) {
  return std::min({lfs_min, separator_term(shortest_separator), decoupling_area_term(criteria)});
}

} // namespace pdd
