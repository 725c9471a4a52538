/// \file interface_split.hpp
/// Lemma 9 of the dissertation: splitting a separator segment into nu equal pieces of length
/// in [2k/sqrt 3, 2k), and the one formula that places the split points.
#pragma once

#include <pdd/core/point.hpp>
#include <pdd/errors.hpp>

#include <cmath>
#include <string>

namespace pdd {

/// The number of pieces nu of Lemma 9 for a separator segment of length `length`:
/// 2 (nu - 1) k <= length < 2 nu k, so each of the nu equal pieces is shorter than 2k and,
/// when k <= length / 4 (eq. 6.1, which gives nu >= 3), at least 2 (nu - 1) k / nu >= 4k/3
/// > 2k / sqrt 3; when k <= sqrt 3 length / 4 (pdd::separator_term), nu >= 2 and the
/// pieces are at least 2k / sqrt 3 too. nu is raised by one where rounding would leave a
/// piece within a relative 1e-12 of 2k, so that pieces computed in floating point stay
/// strictly below 2k.
/// \pre length > 0 and k > 0, both finite.
/// \throws pdd::decoupling_error on a violated precondition; pdd::limit_error when nu would
/// exceed 2^31. Complexity O(1).
inline index_t interface_split_count(double length, double k) {
  if (!(length > 0.0) || !std::isfinite(length) || !(k > 0.0) || !std::isfinite(k))
    throw decoupling_error("cannot split a separator segment of length " + std::to_string(length) +
                           " with k = " + std::to_string(k));
  const double q = std::floor(length / (2.0 * k));
  if (!(q < 2147483647.0))
    throw limit_error("a separator segment of length " + std::to_string(length) +
                      " would be split into more than 2^31 pieces (k = " + std::to_string(k) + ")");
  auto nu = static_cast<index_t>(q) + 1;
  while (length / static_cast<double>(nu) >= 2.0 * k * (1.0 - 1e-12))
    ++nu;
  return nu;
}

/// The i-th of the nu - 1 split points of the segment ab (0 < i < nu), from its canonical
/// orientation: a must be the lexicographically smaller endpoint, so that both subdomains
/// beside an interface compute the same point, p_i = a + (b - a) * (i / nu).
/// Complexity O(1).
inline point interface_split_point(point a, point b, index_t i, index_t nu) {
  const double t = static_cast<double>(i) / static_cast<double>(nu);
  return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t};
}

} // namespace pdd
