/// \file graded_path.hpp
/// Implementation of pdd::pipeline: the graded decoupling path with shields (dissertation 7.4-7.5
/// and 8.3, Theorems 22 and 26): m(D_i) per subdomain, the graded shields, then the path.
#pragma once

#include <pdd/concepts/executor.hpp>
#include <pdd/core/decomposition.hpp>
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/decoupling/graded_decouple.hpp>
#include <pdd/madd/gradation_control.hpp>
#include <pdd/pipeline/detail/sizing_plan.hpp>
#include <pdd/pipeline/statistics.hpp>
#include <pdd/shielding/graded_shields.hpp>
#include <pdd/shielding/shield_decomposition.hpp>
#include <pdd/sizing/any_sizing.hpp>

#include <algorithm>
#include <utility>
#include <vector>

namespace pdd::detail {

/// m(D_i) per subdomain of d: Algorithm 7.1's bounds when it made d (gradation.bounds, one per
/// subdomain), else the field's lower bound over each subdomain (subdomain_sizing_minima);
/// combined with max_area.
template <Executor E>
std::vector<double> subdomain_area_bounds(const gradation_report& gradation, const decomposition& d,
                                          const any_sizing& sizing, double max_area,
                                          const E& executor) {
  std::vector<double> lo;
  if (gradation.bounds.size() == d.subdomains.size())
    for (const sizing_bounds& b : gradation.bounds)
      lo.push_back(b.lo);
  else
    lo = subdomain_sizing_minima(d, sizing, executor);
  for (double& x : lo)
    x = std::min(x, max_area);
  return lo;
}

/// The graded path and the shields it was built with.
struct graded_path_build {
  graded_decoupling graded;
  std::vector<subdomain_shields> shields; ///< per subdomain (empty: no small angles)
};

/// Shields the small angles of d in place, each in the subdomain that holds it, with Theorem
/// 26's l_i from m(D_i) = area_bounds[i] (pdd::shield_graded_decomposition), capped at
/// shield_length_cap(k_i), k_i the graded decoupling parameter of the unshielded subdomain
/// (pdd::graded_subdomain_k: the interface pieces of D_i are built for it, and a shield edge is
/// safe from splitting like a piece when shorter than 2 k_i); then builds the graded path on the
/// shielded decomposition (pdd::decouple_graded: k_i from lfs_min(D_i') and m(D_i), relation
/// 7.1 checked on every separator segment). The kernel's run-time check (mesh_subdomain) still
/// rejects a split shield edge.
/// \throws as pdd::graded_subdomain_k, pdd::shield_graded_decomposition, pdd::decouple_graded.
template <Executor E>
graded_path_build build_graded_path(decomposition& d, const mesh_criteria& criteria,
                                    const std::vector<double>& area_bounds, const E& executor) {
  graded_path_build b;
  if (has_small_angles(d)) {
    std::vector<double> cap = graded_subdomain_k(d, criteria, area_bounds, executor);
    for (double& c : cap)
      c = shield_length_cap(c);
    b.shields = shield_graded_decomposition(d, area_bounds, executor, cap);
  }
  b.graded = decouple_graded(d, criteria, area_bounds, executor);
  return b;
}

/// The pipeline's graded path on d: m(D_i) from subdomain_area_bounds (Algorithm 7.1's bounds,
/// else the minima of `sizing`, the path's field; at most criteria.max_area), then
/// build_graded_path; the shields go to `shields` and k_i (with the largest ratio across an
/// interface and the subdomains a short separator lowered) to `st`.
/// \throws as build_graded_path.
template <Executor E>
decoupled_decomposition
graded_pipeline_path(decomposition& d, const mesh_criteria& criteria, const any_sizing& sizing,
                     const gradation_report& gradation, const E& executor, generate_statistics& st,
                     std::vector<subdomain_shields>& shields) {
  const std::vector<double> lo =
      subdomain_area_bounds(gradation, d, sizing, criteria.max_area, executor);
  graded_path_build b = build_graded_path(d, criteria, lo, executor);
  shields = std::move(b.shields);
  st.subdomain_k = std::move(b.graded.subdomain_k);
  st.k_ratio_max = b.graded.k_ratio_max;
  st.lowered_k = b.graded.lowered_k;
  st.graded_path = true;
  return std::move(b.graded.path);
}

} // namespace pdd::detail
