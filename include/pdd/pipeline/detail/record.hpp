/// \file record.hpp
/// Implementation of pdd::pipeline: what its stages write into generate_statistics, and the
/// shortest interface edge of a decomposition.
#pragma once

#include <pdd/core/decomposition.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/decoupling/decoupled_decomposition.hpp>
#include <pdd/madd/gradation_control.hpp>
#include <pdd/meshing/meshing_statistics.hpp>
#include <pdd/pipeline/options.hpp>
#include <pdd/pipeline/statistics.hpp>
#include <pdd/sizing/mesh_size_estimate.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

namespace pdd::detail {

/// Algorithm 7.1's options as the pipeline's graded stage 1 sets them: o.gradation with the
/// uniform bound, the mean triangle area fraction, Condition 3's T for automatic N, and at
/// least n subdomains.
inline gradation_options graded_stage_options(const generate_options& o, std::size_t n) {
  gradation_options go = o.gradation;
  go.max_area = o.criteria.max_area;
  go.mean_area_fraction = mean_triangle_area_fraction;
  if (o.subdomains == 0) go.max_subdomain_triangles = o.planning.target_subdomain_triangles;
  go.min_subdomains = n;
  go.max_subdomains = std::max(go.max_subdomains, go.min_subdomains);
  return go;
}

/// Algorithm 7.1's measurements in the statistics.
inline void record_gradation(const gradation_report& rep, generate_statistics& st) {
  st.gradation_controlled = true;
  st.r1_max = rep.r1_max;
  st.r2_max = rep.r2_max;
  st.condition_1_unmet = rep.condition_1_unmet;
  st.condition_2_unmet = rep.condition_2_unmet;
  st.gradation_capped = rep.capped;
}

/// The decoupling path's numbers in the statistics (stage 2).
inline void record_path(const decoupled_decomposition& d, generate_statistics& st) {
  st.shielded_triangles = d.num_shielded_triangles();
  st.k = d.k;
  st.lfs_min = d.lfs_min;
  st.shortest_separator = d.shortest_separator;
  st.split_points = d.num_split_points();
}

/// The decoupled meshing's numbers in the statistics (stage 3, N > 1).
inline void record_meshing(meshing_statistics&& ms, const decoupled_decomposition& d,
                           generate_statistics& st) {
  st.triangles = ms.triangles();
  st.interface_splits = ms.interface_splits;
  st.shield_splits = ms.shield_splits;
  st.shielded_triangles = d.num_shielded_triangles();
  st.remeshed_subdomains = ms.remeshed_subdomains;
  st.repair_rounds = ms.repair_rounds;
  st.split_points = d.num_split_points();
  st.per_subdomain = std::move(ms.subdomains);
}

/// Forgets everything a decomposition put into the statistics (the plan falls back to N = 1).
inline void reset_decoupling_statistics(generate_statistics& st) {
  st.monolithic_fallback = true;
  st.subdomains = 1;
  st.graded_path = false;
  st.subdomain_k.clear();
  st.k_ratio_max = 0.0;
  st.k = st.lfs_min = st.shortest_separator = 0.0;
  st.split_points = 0;
  st.shielded_triangles = 0;
  st.decomposition = {};
  st.lowered_k = 0;
  st.gradation_controlled = st.gradation_capped = false;
  st.r1_max = st.r2_max = 0.0;
  st.condition_1_unmet = st.condition_2_unmet = 0;
}

/// The length of the shortest interface edge of d (infinity without one).
inline double shortest_interface_edge(const decomposition& d) {
  double shortest = std::numeric_limits<double>::infinity();
  for (const subdomain& sd : d.subdomains)
    for (std::size_t l = 0; l < sd.loops.size(); ++l)
      for (std::size_t i = 0; i < sd.loops[l].size(); ++i)
        if (sd.tags[l][i].type == edge_tag::kind::interface) {
          const point a = d.vertices[sd.loops[l][i]];
          const point b = d.vertices[sd.loops[l][(i + 1) % sd.loops[l].size()]];
          shortest = std::min(shortest, std::hypot(b.x - a.x, b.y - a.y));
        }
  return shortest;
}

} // namespace pdd::detail
