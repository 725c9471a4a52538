/// \file subdomain_shields.hpp
/// pdd::shield_subdomains: Algorithm 8.2 of the dissertation on a decomposition with a length
/// rule l_i per subdomain: every subdomain with external boundary angles < 60 deg is shielded
/// independently (in parallel). The uniform rule is pdd::shield_decomposition
/// (shield_decomposition.hpp), the graded one pdd::shield_graded_decomposition
/// (graded_shields.hpp).
#pragma once

#include <pdd/concepts/executor.hpp>
#include <pdd/core/decomposition.hpp>
#include <pdd/errors.hpp>
#include <pdd/geometry/lfs.hpp>
#include <pdd/madd/subdomain_pslg.hpp>
#include <pdd/parallel/sequential_executor.hpp>
#include <pdd/shielding/detail/plan.hpp>
#include <pdd/shielding/detail/shield_subdomains.hpp>
#include <pdd/shielding/shield_triangle.hpp>

#include <concepts>
#include <limits>
#include <vector>

namespace pdd {

/// The shielding of one subdomain (see shield_subdomains).
struct subdomain_shields {
  std::vector<shield_triangle> triangles;                   ///< T(D_i); vertex ids are pool ids
  double l = std::numeric_limits<double>::infinity();       ///< l_i (Algorithm 8.2 line 5)
  double lfs_min = std::numeric_limits<double>::infinity(); ///< lfs_min(D_i) before shielding
};

/// Shields the small angles of every subdomain of d in place (Algorithm 8.2, steps 4-14) with
/// l_i = length(i, theta, lfs_min(D_i)), theta the subdomain's angles per loop (degrees, 0 where
/// not shielded; see detail::shield_angles): the shield points b', c' at |ab'| = |ac'| of
/// eq. 8.1 are appended to the vertex pool (marker: their segment's), and the apex a is replaced
/// in its loop by c', b' with the shield edge c' -> b' tagged external with pdd::shield_marker
/// (id no_index). Subdomain areas drop by the shielded triangles' areas. Subdomains without
/// small angles are unchanged (their lfs_min is not computed), so a decomposition without any
/// is unchanged. l_i must not exceed lfs_min(D_i) (Lemma 23: the shield points then fit).
/// \returns per subdomain its shielded triangles (empty for most), l_i and lfs_min(D_i).
/// \pre d as MADD makes it: outer loop counter-clockwise, holes clockwise.
/// \throws pdd::decomposition_error when a small angle has a separator as one of its sides
/// (MADD's angle criterion C1 with Phi0 >= 60 deg excludes it); pdd::geometry_error naming the
/// vertices when two shield points do not fit on a segment. Complexity: lfs_min of every
/// subdomain with small angles, in parallel, plus linear work. The result is the same for
/// every executor (the pool grows sequentially, in subdomain order).
template <Executor E, typename L>
requires std::invocable < const L&, std::size_t, const std::vector<std::vector<double>>
&, double > std::vector<subdomain_shields> shield_subdomains(decomposition& d, const E& executor,
                                                             const L& length) {
  const std::size_t m = d.subdomains.size();
  std::vector<subdomain_shields> out(m);
  std::vector<std::vector<std::vector<double>>> theta(m), dist(m);
  std::vector<double> work(m);
  for (std::size_t s = 0; s < m; ++s)
    for (const auto& loop : d.subdomains[s].loops)
      work[s] += static_cast<double>(loop.size());
  // The executor rethrows the original exception of the smallest failing subdomain.
  executor.run(work, [&](index_t s) {
    theta[s] = detail::subdomain_small_angles(d, s);
    if (!detail::any_small_angle(theta[s])) return;
    pslg g;
    std::vector<index_t> unused;
    detail::build_subdomain_pslg(
        d, s, g, [](std::size_t, index_t, index_t, pslg&) { return no_index; }, unused,
        interface_marker);
    out[s].lfs_min = lfs_min(g);
    out[s].l = length(s, theta[s], out[s].lfs_min);
    for (std::size_t l = 0; l < d.subdomains[s].loops.size(); ++l)
      dist[s].push_back(detail::shield_distances(detail::loop_points(d, d.subdomains[s].loops[l]),
                                                 theta[s][l], out[s].l, d.subdomains[s].loops[l]));
  });
  for (std::size_t s = 0; s < m; ++s)
    if (!dist[s].empty())
      out[s].triangles = detail::place_subdomain_shields(d, s, dist[s], theta[s]);
  return out;
}

} // namespace pdd
