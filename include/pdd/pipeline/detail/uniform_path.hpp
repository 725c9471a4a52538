/// \file uniform_path.hpp
/// Implementation of pdd::pipeline: the uniform decoupling path (one k, Theorem 15) with its
/// shields, used where decoupling.k_override or decoupling.k_scale set k.
#pragma once

#include <pdd/concepts/executor.hpp>
#include <pdd/core/decomposition.hpp>
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/decoupling/decouple.hpp>
#include <pdd/decoupling/decoupled_decomposition.hpp>
#include <pdd/decoupling/decoupling_parameter.hpp>
#include <pdd/pipeline/detail/record.hpp>
#include <pdd/pipeline/options.hpp>
#include <pdd/shielding/shield_decomposition.hpp>

#include <algorithm>
#include <vector>

namespace pdd::detail {

/// The decoupling parameter of the unshielded decomposition d: k_override, or k_scale times
/// Theorem 15's k (caps the shields' l_i through pdd::shield_length_cap).
template <Executor E>
double unshielded_k(const decomposition& d, const decoupling_path_options& o,
                    const mesh_criteria& criteria, const E& executor) {
  if (o.k_override > 0.0) return o.k_override;
  const std::vector<double> lfs = subdomain_lfs(d, executor);
  return o.k_scale * decoupling_parameter(*std::min_element(lfs.begin(), lfs.end()),
                                          shortest_interface_edge(d), criteria);
}

/// The uniform path: the small angles of d shielded in place with the domain-wide bound
/// (pdd::shield_decomposition, l capped by shield_length_cap of the unshielded k), then
/// pdd::decouple. Returns the path; `shields` receives the shields.
template <Executor E>
decoupled_decomposition build_uniform_path(decomposition& d, const decoupling_path_options& o,
                                           const mesh_criteria& criteria, const E& executor,
                                           std::vector<subdomain_shields>& shields) {
  shields.clear();
  if (has_small_angles(d))
    shields = shield_decomposition(d, criteria.max_area, executor,
                                   shield_length_cap(unshielded_k(d, o, criteria, executor)));
  return pdd::decouple(d, decoupling_options{criteria, o.k_override, o.k_scale}, executor);
}

} // namespace pdd::detail
