/// \file decompose.hpp
/// pdd::decompose: the Medial Axis Domain Decomposition (dissertation ch. 3-4, 5.1) of a
/// domain into N subdomains whose separators meet the boundary and each other at angles
/// >= Phi0.
#pragma once

#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/madd/detail/assemble.hpp>
#include <pdd/madd/detail/region.hpp>
#include <pdd/madd/detail/split.hpp>
#include <pdd/errors.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/madd/decomposition.hpp>
#include <pdd/madd/decomposition_measures.hpp>
#include <pdd/madd/madd_options.hpp>
#include <pdd/partition/default_partitioner.hpp>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <string>
#include <vector>

namespace pdd {

namespace detail {

inline void check_madd_options(const madd_options& o) {
  auto bad = [](const std::string& what) { throw decomposition_error("madd_options: " + what); };
  if (!(o.min_separator_angle_deg > 0.0 && o.min_separator_angle_deg < 90.0))
    bad("min_separator_angle_deg must be in (0, 90)");
  if (o.algorithm != 1 && o.algorithm != 2) bad("algorithm must be 1 or 2");
  if (!(o.refinement_factor > 0.0) || !std::isfinite(o.refinement_factor))
    bad("refinement_factor must be positive and finite");
  if (o.max_refinement_levels < 1 || o.max_refinement_levels > 30)
    bad("max_refinement_levels must be in [1, 30]");
  if (o.max_encroachment_depth < 0 || o.max_encroachment_depth > 30)
    bad("max_encroachment_depth must be in [0, 30]");
  if (!(o.imbalance_bound >= 0.5 && o.imbalance_bound <= 1.0))
    bad("imbalance_bound must be in [0.5, 1]");
  if (!(o.max_part_fraction >= 0.5 && o.max_part_fraction <= 1.0))
    bad("max_part_fraction must be in [0.5, 1]");
  if (!(o.max_subdomain_area > 0.0)) bad("max_subdomain_area must be positive");
  if (!(o.round_fraction > 0.0 && o.round_fraction <= 1.0)) bad("round_fraction must be in (0, 1]");
  if (!std::isfinite(o.max_subdomain_area) && o.subdomains < 1) bad("subdomains must be >= 1");
}

/// Target boundary length h (refinement level 0) for a split of r (4.1).
inline double target_length(const madd_region& r, const madd_options& o, double global_h) {
  if (o.refinement_scale == madd_refinement_scale::global) return global_h;
  return 4.0 * r.area / (region_perimeter(r) * o.refinement_factor);
}

} // namespace detail

/// Decomposes the domain of g into subdomains by MADD (dissertation ch. 3-4): N-way by divide
/// and conquer (3.7), the largest subdomains first, concurrently in rounds (4.3: a round
/// splits the min(count, N - count) largest subdomains, each split a pure function of its
/// subdomain, so the result is bitwise identical for every thread count), with dynamic
/// refinement (4.1), smoothing (4.2) and the connectivity and angle repairs of 5.1.
///
/// Guarantees: exactly N subdomains (or all with area <= max_subdomain_area), each a polygon
/// with holes; every separator angle with the boundary or another separator >= Phi0 (input
/// angles below Phi0 stay, no separator ends there); both sides of an interface share vertex
/// ids; see validate_decomposition().
/// \tparam P a GraphPartitioner (default: METIS when found).
/// \pre g's segments form closed loops that do not intersect (validate()).
/// \throws geometry_error as find_loops for bad input; decomposition_error for bad options, or
/// when the domain cannot be split as asked (a subdomain too thin or with too few junction
/// triangles after max_refinement_levels: the message names the subdomain and the reason).
/// Complexity: about O(sum over splits of |Z| log |Z|); N = 1024 on a pipe cross-section takes
/// well under a second on one core. Thread-safety: reentrant (no shared state).
template <GraphPartitioner P = default_partitioner>
decomposition decompose(const pslg& g, const madd_options& o = {}, const P& partitioner = {},
                        decomposition_statistics* stats = nullptr) {
  const auto t0 = std::chrono::steady_clock::now();
  detail::check_madd_options(o);
  std::vector<detail::madd_region> regions = detail::regions_of(g);
  if (regions.empty()) throw decomposition_error("MADD: the PSLG bounds no domain");
  const bool by_area = std::isfinite(o.max_subdomain_area);
  double total_area = 0.0;
  for (const auto& r : regions)
    total_area += r.area;
  if (!by_area && o.subdomains < regions.size())
    throw decomposition_error("MADD: the domain has " + std::to_string(regions.size()) +
                              " connected components, more than the " +
                              std::to_string(o.subdomains) + " subdomains asked for");
  double global_h = 0.0;
  {
    double len = 0.0;
    std::size_t n = 0;
    for (const auto& r : regions) {
      len += detail::region_perimeter(r);
      n += detail::region_vertex_count(r);
    }
    const double target_n = by_area ? std::max(1.0, total_area / o.max_subdomain_area)
                                    : static_cast<double>(o.subdomains);
    global_h = len / static_cast<double>(n) / (o.refinement_factor * std::sqrt(target_n));
  }
  detail::madd_split_options so;
  so.graph.algorithm = o.algorithm;
  so.graph.phi0 = o.min_separator_angle_deg;
  so.graph.phi0_accept = o.min_separator_angle_deg + 1e-7;
  so.graph.smoothing = o.smoothing;
  so.max_levels = o.max_refinement_levels;
  so.max_encroachment_depth = o.max_encroachment_depth;
  so.imbalance_bound = o.imbalance_bound;
  so.max_part_fraction = o.max_part_fraction;

  decomposition_statistics st;
  std::vector<char> final_region(regions.size(), 0);
  std::vector<std::string> why(regions.size());
  tbb::task_arena arena(o.threads == 0 ? tbb::task_arena::automatic : static_cast<int>(o.threads));
  for (;;) {
    // Choose this round's regions: the largest first (ties: lower index).
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < regions.size(); ++i)
      if (!final_region[i] && (!by_area || regions[i].area > o.max_subdomain_area))
        order.push_back(i);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return regions[a].area > regions[b].area;
    });
    const bool done = by_area ? order.empty() : regions.size() >= o.subdomains;
    if (done) break;
    if (order.empty()) {
      std::string msg = "MADD: cannot split the domain into " +
                        (by_area ? "subdomains of area <= " + std::to_string(o.max_subdomain_area)
                                 : std::to_string(o.subdomains) + " subdomains") +
                        " (reached " + std::to_string(regions.size()) + ")";
      for (std::size_t i = 0; i < regions.size(); ++i)
        if (final_region[i] && (!by_area || regions[i].area > o.max_subdomain_area))
          msg += "; subdomain " + std::to_string(i) + " (area " + std::to_string(regions[i].area) +
                 ", " + std::to_string(detail::region_vertex_count(regions[i])) +
                 " vertices): " + why[i];
      throw decomposition_error(msg);
    }
    // Split together only what a sequential largest-first loop would split next: regions
    // of at least round_fraction times the largest area (their children are smaller than
    // that as long as splits are balanced to round_fraction, so no child would be split
    // before them).
    const double cut = o.round_fraction * regions[order[0]].area;
    std::size_t take = 0;
    while (take < order.size() && regions[order[take]].area >= cut)
      ++take;
    if (!by_area) take = std::min(take, o.subdomains - regions.size());
    order.resize(take);
    std::vector<detail::madd_split_result> res(order.size());
    arena.execute([&] {
      tbb::parallel_for(std::size_t{0}, order.size(), [&](std::size_t k) {
        detail::madd_split_options sk = so;
        sk.target_length = detail::target_length(regions[order[k]], o, global_h);
        res[k] = detail::split_region(regions[order[k]], sk, partitioner);
      });
    });
    ++st.rounds;
    std::vector<detail::madd_edge_split> reg;
    std::vector<detail::madd_region> next;
    std::vector<char> next_final;
    std::vector<std::string> next_why;
    std::vector<int> split_of(regions.size(), -1);
    for (std::size_t k = 0; k < order.size(); ++k)
      split_of[order[k]] = static_cast<int>(k);
    for (std::size_t i = 0; i < regions.size(); ++i) {
      const int k = split_of[i];
      st.levels_tried += k >= 0 ? res[k].levels_tried : 0;
      if (k >= 0 && res[k].ok) {
        auto& r = res[k];
        ++st.splits;
        st.repairs += r.repairs;
        st.smoothing_moves += r.smoothing_moves;
        st.algorithm_fallbacks += r.fallback ? 1 : 0;
        st.boundary_points += r.z_points;
        st.mean_split_fraction += r.max_fraction;
        st.max_split_fraction = std::max(st.max_split_fraction, r.max_fraction);
        if (st.splits_per_level.size() <= static_cast<std::size_t>(r.level))
          st.splits_per_level.resize(r.level + 1, 0);
        ++st.splits_per_level[r.level];
        reg.insert(reg.end(), r.kept.begin(), r.kept.end());
        for (auto& c : r.children) {
          next.push_back(std::move(c));
          next_final.push_back(0);
          next_why.emplace_back();
        }
      } else {
        next.push_back(std::move(regions[i]));
        next_final.push_back(k >= 0 ? 1 : final_region[i]);
        next_why.push_back(k >= 0 ? res[k].failure : why[i]);
        st.failed_splits += k >= 0 ? 1 : 0;
      }
    }
    regions = std::move(next);
    final_region = std::move(next_final);
    why = std::move(next_why);
    detail::apply_edge_splits(regions, std::move(reg));
  }
  if (st.splits > 0) st.mean_split_fraction /= static_cast<double>(st.splits);
  decomposition d = detail::assemble_decomposition(regions);
  if (stats) {
    st.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    measure_decomposition(d, st);
    *stats = std::move(st);
  }
  return d;
}

} // namespace pdd
