/// \file shield_decomposition.hpp
/// pdd::shield_decomposition: Algorithm 8.2 of the dissertation on a decomposition: every
/// subdomain with external boundary angles < 60 deg is shielded independently (in parallel),
/// under one area bound (the uniform method; the graded one is graded_shields.hpp).
#pragma once

#include <pdd/concepts/executor.hpp>
#include <pdd/core/decomposition.hpp>
#include <pdd/errors.hpp>
#include <pdd/parallel/sequential_executor.hpp>
#include <pdd/shielding/detail/plan.hpp>
#include <pdd/shielding/subdomain_shields.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace pdd {

/// The cap on l_i for a decomposition whose unshielded decoupling parameter is k0:
/// sqrt 3 k0, less one part in 1e9 for rounding (see shield_decomposition). Complexity O(1).
inline double shield_length_cap(double k0) {
  return std::sqrt(3.0) * k0 * (1.0 - 1e-9);
}

/// Shields the small angles of every subdomain of d in place (Algorithm 8.2 with the uniform
/// area bound m(D_i) = area_bound): l_i = min over its angles theta < 60 deg of
/// {(1 + 2 sin(theta/2)) sqrt(2 A sin theta), sqrt(A / sqrt 2), lfs_min(D_i)}, the shield
/// points b', c' at eq. 8.1 are appended to the vertex pool (marker: their segment's), and the
/// apex a is replaced in its loop by the shield points with the shield edge between them
/// tagged external with pdd::shield_marker (id no_index; see pdd::shield_subdomains). Subdomain
/// areas drop by the shielded triangles' areas. Subdomains without small angles are unchanged, so a
/// decomposition without any is unchanged. The shielded loops are what pdd::decouple then sees: its
/// k uses lfs_min(D_i') (Theorem 24 (3): > l_i / sqrt 3). `max_l` caps every l_i. With a decoupling
/// path it must be at most sqrt 3 k0, k0 the decoupling parameter of the unshielded decomposition
/// (pdd::pipeline passes shield_length_cap(k0)): the separators are split into pieces shorter than
/// 2k, which makes every subdomain's features as small as k, and a shield edge is then safe from
/// splitting like an interface piece only when it is shorter than 2k. With l_i <= sqrt 3 k0 and k =
/// min(k0, lfs_min(D_i')): |b'c'| = l_i / (cos(theta/2) + sin theta) <= l_i < 2 k0, and, when
/// lfs_min(D_i') is the smaller, lfs_min(D_i') > l_i / 2 (Lemma 23 (iii) gives l_i / sqrt 3 for
/// theta <= 30 deg; tests/shielding measures > l_i / 2 up to 59 deg) while |b'c'| < l_i since
/// cos(theta/2) + sin theta > 1. The cap sqrt 3 k0 (rather than k0) keeps lfs_min(D_i') >= k0, so k
/// = k0 and the shields do not shorten the interface pieces (measured from 10 to 59 deg in
/// tests/shielding; with the cap k0, k fell to 0.58-0.85 k0). Below about 7 deg the area term of
/// l_i is itself shorter than sqrt 3 k0 and k falls with it. (Theorem 24 (5) assumes |b'c'| < 2
/// lfs_min(D_i) suffices; in a thin tip subdomain meshed with a global k << lfs_min(D_i), CGAL
/// splits such a shield edge.) \returns per subdomain its shielded triangles (empty for most). \pre
/// d as MADD makes it: outer loop counter-clockwise, holes clockwise. \throws
/// pdd::decomposition_error when a small angle has a separator as one of its sides (MADD's angle
/// criterion C1 with Phi0 >= 60 deg excludes it); pdd::geometry_error as pdd::shield. Complexity:
/// lfs_min of every subdomain with small angles, in parallel, plus linear work. The result is the
/// same for every executor.
template <Executor E = sequential_executor>
std::vector<subdomain_shields>
shield_decomposition(decomposition& d, double area_bound, const E& executor = {},
                     double max_l = std::numeric_limits<double>::infinity()) {
  return shield_subdomains(
      d, executor, [&](std::size_t, const std::vector<std::vector<double>>& theta, double lfs) {
        return std::min(max_l, detail::shield_length(theta, lfs, area_bound));
      });
}

} // namespace pdd

namespace pdd::detail {
/// True when some subdomain of d has a domain-side angle < 60 deg (loops are walked with the
/// domain on their left). Complexity O(size of d).
inline bool has_small_angles(const decomposition& d) {
  for (const subdomain& sd : d.subdomains)
    for (const auto& loop : sd.loops) {
      const std::size_t n = loop.size();
      for (std::size_t i = 0; i < n; ++i)
        if (ccw_angle_deg(d.vertices[loop[i]], d.vertices[loop[(i + 1) % n]],
                          d.vertices[loop[(i + n - 1) % n]]) < shield_threshold_deg)
          return true;
    }
  return false;
}
} // namespace pdd::detail
