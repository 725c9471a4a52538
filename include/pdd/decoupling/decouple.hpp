/// \file decouple.hpp
/// pdd::decouple: turns a decomposition into a decoupled decomposition by refining its
/// separators into a decoupling path (dissertation 6.2-6.3, Lemma 9, Theorem 15).
#pragma once

#include <pdd/concepts/executor.hpp>
#include <pdd/core/decomposition.hpp>
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/decoupling/decoupled_decomposition.hpp>
#include <pdd/decoupling/decoupling_parameter.hpp>
#include <pdd/decoupling/detail/build.hpp>
#include <pdd/decoupling/interface_split.hpp>
#include <pdd/errors.hpp>
#include <pdd/geometry/lfs.hpp>
#include <pdd/madd/subdomain_pslg.hpp>
#include <pdd/parallel/sequential_executor.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace pdd {

/// Options of pdd::decouple.
struct decoupling_options {
  /// The criteria the subdomains will be meshed with (the area bound enters k, Theorem 15).
  mesh_criteria criteria;
  /// > 0: use this k instead of Theorem 15's (experiments and tests; the decoupling guarantee
  /// then holds only if it does not exceed the computed k).
  double k_override = 0.0;
  /// Multiplies the computed k (values in (0, 1] keep the guarantee).
  double k_scale = 1.0;
};

namespace detail {

/// lfs_min of every subdomain's loops (without split points), computed concurrently.
///
/// Why min_i lfs_min(B_i) is the right value for lfs_min(D_H) in eq. 6.1. pdd::lfs_min is
/// Definition 7: the minimum distance between two non-incident entities (vertices, segments)
/// whose connecting segment lies in the closed domain.
/// - lfs_min(B_i) >= lfs_min(D_H) for every subdomain boundary B_i: its entities are entities
///   of D_H with the same incidences, and a connecting segment inside D_i lies inside the
///   domain, so every pair counted for B_i is counted for D_H.
/// - The proofs only need the per-subdomain values: Proposition 12 and Theorem 15 apply
///   Theorem 1 to each B_i (with its split points) on its own, and Lemma 11's argument (a split
///   point is >= lfs_min away from non-incident entities and >= sin 60 * 2k/sqrt 3 = k from
///   incident ones) runs unchanged inside one B_i. So k <= min_i lfs_min(B_i) is sufficient.
/// - The values coincide when a closest pair of D_H is joined inside one subdomain. A pair
///   joined across a separator segment s = uv is not closer than pairs of one subdomain: s
///   itself (on both boundaries) is nearer to each end unless both entities are incident to
///   s, one at u and one at v, where the >= 60 deg angles bound the distance as in Lemma 11
///   (two 60 deg corners give equality). Pairs across holes do not count in Definition 7, and
///   the kernel, meshing each subdomain alone, never sees the other side of a separator.
template <Executor E>
std::vector<double> subdomain_lfs(const decomposition& d, const E& ex) {
  const std::size_t m = d.subdomains.size();
  std::vector<double> lfs(m, std::numeric_limits<double>::infinity());
  std::vector<double> work(m);
  for (std::size_t s = 0; s < m; ++s) {
    std::size_t n = 0;
    for (const auto& loop : d.subdomains[s].loops)
      n += loop.size();
    work[s] = static_cast<double>(n);
  }
  // The executor rethrows the original exception of the smallest failing subdomain.
  ex.run(work, [&](index_t s) {
    pslg g;
    std::vector<index_t> unused;
    build_subdomain_pslg(
        d, s, g, [](std::size_t, index_t, index_t, pslg&) { return no_index; }, unused,
        interface_marker);
    lfs[s] = lfs_min(g);
  });
  return lfs;
}

} // namespace detail

/// Refines the separators of d into a decoupling path: computes
/// k = min(lfs_min(D_H), sqrt 3 L / 4, (1/2) sqrt(A / sqrt 2)) (Theorem 15; Proposition 12
/// without an area bound; the text's L / 4 relaxed, see separator_term) with lfs_min taken
/// per subdomain in parallel, and splits every separator segment into nu equal pieces,
/// 2k/sqrt 3 <= piece < 2k (Lemma 9), from its canonical orientation. Meshing each
/// subdomain's input() with a Ruppert-type DelaunayMesher then never splits a piece
/// (Corollary 13), and the union of the subdomain meshes is a conforming Delaunay mesh
/// (Proposition 7).
/// \tparam E an Executor (the per-subdomain lfs_min runs on it).
/// \pre d is a decomposition as MADD makes it: loops over a shared vertex pool, every interface
/// edge listed by the two subdomains it separates; separators meet the boundary and each other
/// at >= 60 deg (Phi_0).
/// \throws pdd::decoupling_error for a malformed decomposition (naming subdomain and loop) or an
/// unusable k; pdd::geometry_error from lfs_min; pdd::limit_error when a separator segment would
/// need more than 2^31 pieces.
/// Complexity: O(size of d + number of split points) plus lfs_min per subdomain.
/// Thread-safety: reentrant.
template <Executor E = sequential_executor>
decoupled_decomposition decouple(decomposition d, const decoupling_options& options,
                                 const E& executor = {}) {
  detail::check_decomposition(d);
  decoupled_decomposition dd;
  detail::collect_path_edges(d, dd.path, dd.loop_edge_path);
  dd.shortest_separator = std::numeric_limits<double>::infinity();
  for (const path_edge& e : dd.path)
    dd.shortest_separator = std::min(dd.shortest_separator, e.length);
  const std::vector<double> lfs = detail::subdomain_lfs(d, executor);
  dd.lfs_min = *std::min_element(lfs.begin(), lfs.end());
  dd.area_term = decoupling_area_term(options.criteria);
  dd.k = options.k_override > 0.0
             ? options.k_override
             : options.k_scale *
                   decoupling_parameter(dd.lfs_min, dd.shortest_separator, options.criteria);
  if (!(dd.k > 0.0) || !std::isfinite(dd.k))
    throw decoupling_error("unusable decoupling parameter k = " + std::to_string(dd.k) +
                           " (lfs_min " + std::to_string(dd.lfs_min) + ", shortest separator " +
                           std::to_string(dd.shortest_separator) + ")");
  dd.parts = std::move(d);
  for (path_edge& e : dd.path) {
    e.k = dd.k;
    e.pieces = interface_split_count(e.length, dd.k);
  }
  detail::place_split_points(dd);
  return dd;
}

} // namespace pdd
