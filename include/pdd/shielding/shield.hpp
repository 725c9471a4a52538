/// \file shield.hpp
/// pdd::shield: the shielding of small input angles (< 60 deg) of dissertation 8.1
/// (Algorithms 8.1 and 8.2, Lemma 23, Theorem 24) for a pslg domain.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/errors.hpp>
#include <pdd/geometry/lfs.hpp>
#include <pdd/geometry/loops.hpp>
#include <pdd/shielding/detail/plan.hpp>
#include <pdd/shielding/detail/shielded_loops.hpp>
#include <pdd/shielding/shield_triangle.hpp>
#include <pdd/shielding/shielded_domain.hpp>

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

namespace pdd {

/// Shields every angle theta < 60 deg of the domain of g (Algorithm 8.2 for one subdomain):
/// l = min over the small angles of {(1 + 2 sin(theta/2)) sqrt(2 A sin theta), sqrt(A / sqrt 2),
/// lfs_min(g)} (eq. 8.6, A = area_bound; without an area bound l = lfs_min, Algorithm 8.1);
/// b', c' on the two segments at the apex a at |ab'| = |ac'| = l / (2 sin(theta/2)
/// (cos(theta/2) + sin theta)) (eq. 8.1). By Lemma 23 and Theorem 24, D' has no angle below
/// 60 deg, lfs_min(D') > l / sqrt 3, shield edges are never split by Ruppert-type refinement
/// and the shielded triangles have area <= A and ratio 1 / (2 sin theta).
/// \pre g is valid (pdd::validate): closed loops. area_bound > 0 (infinity: none).
/// \throws pdd::geometry_error as find_loops(), or naming the vertices when two shield points
/// would not fit on a segment (cannot happen for a valid domain, Lemma 23 (ii), (iv)).
/// Complexity O(n log n) expected (loops and lfs_min). Thread-safe.
inline shielded_domain shield(const pslg& g, double area_bound) {
  detail::reject_shield_marker(g);
  detail::loops_with_triangulation lt;
  detail::find_loops_into(g, lt);
  shielded_domain out;
  const detail::oriented_loops loops = detail::domain_on_left_loops(lt);
  const std::size_t nl = loops.vertices.size();
  std::vector<std::vector<point>> pts(nl);
  bool any = false;
  std::vector<std::vector<double>> theta(nl);
  for (std::size_t k = 0; k < nl; ++k) {
    for (const index_t v : loops.vertices[k])
      pts[k].push_back(g.vertices[v]);
    theta[k] = detail::shield_angles(pts[k], std::vector<char>(pts[k].size(), 1));
    any = any || std::any_of(theta[k].begin(), theta[k].end(), [](double t) { return t > 0.0; });
  }
  if (!any) {
    out.domain = g;
    return out;
  }
  out.lfs_min = lfs_min(g, lt);
  out.l = detail::shield_length(theta, out.lfs_min, area_bound);
  for (std::size_t k = 0; k < nl; ++k)
    detail::append_shielded_loop(g, loops, k, pts[k], theta[k], out);
  out.domain.holes = g.holes;
  out.domain.regions = g.regions;
  return out;
}

} // namespace pdd
