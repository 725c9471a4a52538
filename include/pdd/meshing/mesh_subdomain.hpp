/// \file mesh_subdomain.hpp
/// pdd::mesh_subdomain: one job of the mesh generation phase (dissertation Algorithm 6.1 step
/// 7, Algorithm 7.2 steps 12-13): the kernel on one decoupled subdomain and the invariance
/// check of its interface pieces; pdd::repair_decoupling_path: one invariance repair round.
/// pdd::mesh_subdomains (threads) and pdd::mpi::mesh_subdomains (MPI ranks) are built on them.
#pragma once

#include <pdd/concepts/delaunay_mesher.hpp>
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/decoupling/decoupled_decomposition.hpp>
#include <pdd/decoupling/invariance.hpp>
#include <pdd/errors.hpp>
#include <pdd/madd/subdomain_pslg.hpp>
#include <pdd/shielding/apply_shields.hpp>
#include <pdd/sizing/any_sizing.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace pdd {

/// Options of pdd::mesh_subdomains.
struct meshing_options {
  mesh_criteria criteria;   ///< the same criteria the decoupling path was built for
  unsigned max_repairs = 3; ///< invariance repair rounds (each halves k on failing segments)
  /// The kernel's sizing field besides criteria.max_area (empty: none). The decoupling path
  /// must have been built for it: k from its minimum (pdd::decouple on lowered criteria) or
  /// k_i from its minimum over each subdomain (pdd::decouple_graded); see pdd::pipeline.
  any_sizing sizing{};
  /// Expected work per subdomain, the order in which the executors start them (largest
  /// first; Algorithm 7.2: the expected triangles of each subdomain, e.g.
  /// gradation_report::expected_triangles). Empty: area / criteria.max_area (pdd::expected_work).
  std::vector<double> expected_work{};
  /// Subdomains whose meshes the sink has already (a resumed run's intact pieces, see
  /// pdd::resumable_piece_sink): not meshed in the first round. An invariance repair round
  /// may still mesh and deliver one of them again (never with a Ruppert-type kernel).
  std::vector<index_t> kept{};
};

/// What pdd::mesh_subdomain made of one subdomain.
struct subdomain_meshing {
  /// The kernel's mesh, triangle markers set to the subdomain id, shield triangles added; to
  /// be delivered only when split_path_edges is empty.
  triangle_mesh mesh;
  /// The interface pieces the kernel split (segment indices of the subdomain input); empty
  /// unless Corollary 13 failed.
  std::vector<index_t> split_pieces;
  /// The decoupling path edges (dd.path indices) of split_pieces, sorted, without repeats.
  std::vector<index_t> split_path_edges;
  double seconds = 0.0; ///< kernel and check time
};

/// Meshes subdomain s of `dd` (its input(), Lemma 9) with `mesher` under `options` and checks
/// that every interface piece is still an edge (Corollary 13, split_interface_pieces). When
/// they all are, the subdomain's shield triangles are added (Algorithm 8.2) and the triangle
/// markers are set to s.
/// \tparam M a DelaunayMesher.
/// \throws pdd::meshing_error(s, ...) for any exception inside (the kernel's, an invariance
/// check's) and when the kernel split a shield edge (Theorem 24 (5) excludes it).
/// Complexity: the kernel on the subdomain plus linear checks. Thread-safety: reentrant for
/// different s (dd, options and mesher are only read).
template <DelaunayMesher M>
subdomain_meshing mesh_subdomain(const decoupled_decomposition& dd, index_t s,
                                 const meshing_options& options, const M& mesher) {
  try {
    const auto t0 = std::chrono::steady_clock::now();
    const subdomain_input in = dd.input(s);
    mesher_result r = mesher.mesh(in.domain, options.criteria, options.sizing);
    subdomain_meshing out;
    out.split_pieces = split_interface_pieces(in, r);
    out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!out.split_pieces.empty()) {
      for (const index_t seg : out.split_pieces)
        out.split_path_edges.push_back(in.segment_path_edge[seg]);
      std::sort(out.split_path_edges.begin(), out.split_path_edges.end());
      out.split_path_edges.erase(
          std::unique(out.split_path_edges.begin(), out.split_path_edges.end()),
          out.split_path_edges.end());
      return out;
    }
    if (s < dd.shields.size() && !dd.shields[s].empty()) {
      const std::size_t ss = add_shield_triangles(r, in.domain, dd.shields[s], static_cast<int>(s));
      if (ss != 0)
        throw meshing_error(s, std::to_string(ss) +
                                   " shield edge(s) were split by the kernel (Theorem 24 (5) "
                                   "excludes it for a Ruppert-type kernel)");
    }
    r.mesh.triangle_markers.assign(r.mesh.triangles.size(), static_cast<int>(s));
    out.mesh = std::move(r.mesh);
    return out;
  } catch (const meshing_error& e) {
    rethrow_for_subdomain(e, static_cast<long long>(s));
  } catch (const std::exception& e) {
    throw meshing_error(s, e.what());
  }
}

/// The expected work of meshing each subdomain of `dd` (dissertation 6.4: the area predicts
/// the mesher's work): area / criteria.max_area, or the area when max_area is unbounded. The
/// executors start subdomains in decreasing order of it (Algorithm 7.2 step 3).
/// Complexity linear in the subdomains' loops.
inline std::vector<double> expected_work(const decoupled_decomposition& dd,
                                         const mesh_criteria& criteria) {
  const bool bounded = std::isfinite(criteria.max_area) && criteria.max_area > 0.0;
  std::vector<double> work(dd.num_subdomains());
  for (index_t s = 0; s < work.size(); ++s)
    work[s] = detail::subdomain_area(dd.parts, s) / (bounded ? criteria.max_area : 1.0);
  return work;
}

/// The expected work of meshing each subdomain under `options`: options.expected_work when
/// given, else expected_work(dd, options.criteria).
/// \throws pdd::meshing_error(-1, ...) when options.expected_work has not one value per
/// subdomain.
inline std::vector<double> expected_work(const decoupled_decomposition& dd,
                                         const meshing_options& options) {
  if (options.expected_work.empty()) return expected_work(dd, options.criteria);
  if (options.expected_work.size() != dd.num_subdomains())
    throw meshing_error(-1, "meshing_options::expected_work has " +
                                std::to_string(options.expected_work.size()) + " values for " +
                                std::to_string(dd.num_subdomains()) + " subdomains");
  return options.expected_work;
}

/// One invariance repair round (pdd::mesh_subdomains): re-splits every path edge in
/// `failures` (subdomain -> its split path edges) with k / 2 and returns the subdomains to
/// mesh again, the failing ones and their neighbours across those edges, sorted. The same
/// failures give the same path on every process (the re-split is deterministic).
/// Complexity: linear in the re-split edges.
inline std::vector<index_t>
repair_decoupling_path(decoupled_decomposition& dd,
                       const std::map<index_t, std::vector<index_t>>& failures) {
  std::set<index_t> redo, edges;
  for (const auto& failure : failures) {
    redo.insert(failure.first);
    edges.insert(failure.second.begin(), failure.second.end());
  }
  for (const index_t e : edges) {
    dd.resplit(e, dd.path[e].k / 2.0);
    redo.insert(dd.path[e].sides[0]);
    redo.insert(dd.path[e].sides[1]);
  }
  return {redo.begin(), redo.end()};
}

/// The message of a decoupling_error for repairs that ran out: the failing subdomains with
/// their split separator segments and k (the first 8, then how many more: the Bahamas at 30 deg
/// listed 300), and, for an angle bound above Ruppert's (criteria), that the path is proven only
/// up to 20.7 deg and how to mesh anyway.
inline std::string describe_path_failures(const decoupled_decomposition& dd,
                                          const std::map<index_t, std::vector<index_t>>& failures,
                                          const mesh_criteria& criteria) {
  constexpr std::size_t listed = 8;
  std::string msg;
  std::size_t count = 0;
  for (const auto& failure : failures)
    for (const index_t e : failure.second)
      if (++count <= listed)
        msg += (msg.empty() ? "" : "; ") + std::string("subdomain ") +
               std::to_string(failure.first) + ", separator segment " +
               std::to_string(dd.path[e].u) + "-" + std::to_string(dd.path[e].v) + " (k " +
               std::to_string(dd.path[e].k) + ")";
  if (count > listed) msg += "; and " + std::to_string(count - listed) + " more";
  if (!criteria.within_ruppert_bound()) {
    char angle[32];
    std::snprintf(angle, sizeof angle, "%g", criteria.min_angle_deg);
    msg += "; the path is proven up to Ruppert's angle bound, 20.7 deg, and the angle bound is " +
           std::string(angle) +
           " deg: mesh the domain whole (one subdomain) or bound the angle at 20.7 deg";
  }
  return msg;
}

} // namespace pdd
