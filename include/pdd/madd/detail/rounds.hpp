/// \file rounds.hpp
/// Implementation of pdd::decompose: option checks, the refinement length, and the rounds of
/// concurrent splits (dissertation 3.7, 4.1, 4.3) over the current leaves of the split tree.
#pragma once

#include <pdd/errors.hpp>
#include <pdd/madd/decomposition_statistics.hpp>
#include <pdd/madd/detail/assemble.hpp>
#include <pdd/madd/detail/quotas.hpp>
#include <pdd/madd/detail/region.hpp>
#include <pdd/madd/detail/split.hpp>
#include <pdd/madd/madd_options.hpp>
#include <pdd/madd/split_policy.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace pdd::detail {

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
  if (!(o.feature_clearance >= 0.0) || !std::isfinite(o.feature_clearance))
    bad("feature_clearance must be finite and >= 0");
  if (!std::isfinite(o.max_subdomain_area) && o.subdomains < 1) bad("subdomains must be >= 1");
  if (o.split_policy && std::isfinite(o.max_subdomain_area))
    bad("max_subdomain_area must stay infinite with a split_policy (the policy decides)");
}

/// Target boundary length h (refinement level 0) for a split of r (4.1).
inline double target_length(const madd_region& r, const madd_options& o, double global_h) {
  if (o.refinement_scale == madd_refinement_scale::global) return global_h;
  return 4.0 * r.area / (region_perimeter(r) * o.refinement_factor);
}

/// A leaf of the split tree: a region, whether it is final (a split of it failed; `why`
/// says how), and, into N subdomains, how many it is to become (quotas.hpp).
struct madd_leaf {
  madd_region region;
  bool final = false;
  std::string why;
  std::size_t quota = 1;
};

/// The leaves of decompose's split tree and the goal (N subdomains, or an area bound).
struct madd_state {
  madd_state(std::vector<madd_region> regions, const madd_options& o)
      : by_area(std::isfinite(o.max_subdomain_area)), by_policy(bool(o.split_policy)),
        by_quota(!by_area && !by_policy) {
    if (regions.empty()) throw decomposition_error("MADD: the PSLG bounds no domain");
    if (!by_area && o.subdomains < regions.size())
      throw decomposition_error(
          "MADD: the domain has " + std::to_string(regions.size()) +
          " connected components (faces, for a general PSLG), more than the " +
          std::to_string(o.subdomains) + " subdomains asked for");
    for (auto& r : regions)
      leaves.push_back({std::move(r), false, {}, 1});
    if (by_quota) allot(o.subdomains);
  }
  bool by_area;   ///< split until every area <= max_subdomain_area (3.7), else into N
  bool by_policy; ///< madd_options::split_policy decides (4.4, 7.3)
  bool by_quota;  ///< into N: every leaf is split until its quota is 1 (quotas.hpp)
  std::vector<madd_leaf> leaves;
  std::vector<double> priority; ///< by_policy: the policy's priority of every leaf

  /// Asks the split policy for the priority of every leaf (by_policy only).
  /// \throws decomposition_error when it returns the wrong number of priorities.
  void update_priorities(const madd_options& o) {
    if (!by_policy) return;
    std::vector<madd_leaf_view> views(leaves.size());
    for (std::size_t i = 0; i < leaves.size(); ++i) {
      views[i].area = leaves[i].region.area;
      views[i].keep_whole = leaves[i].region.keep_whole;
      for (const madd_loop& l : leaves[i].region.loops)
        views[i].loops.emplace_back(l.points);
    }
    priority = o.split_policy(views);
    if (priority.size() != leaves.size())
      throw decomposition_error("MADD: the split policy returned " +
                                std::to_string(priority.size()) + " priorities for " +
                                std::to_string(leaves.size()) + " subdomains");
  }
  /// Shares n subdomains among the leaves (quotas.hpp): 1 each, and the rest to the leaves
  /// that can still be split (not final, not kept whole), the largest area per subdomain
  /// first. A final leaf keeps the quota it failed with (throw_unsplittable names it).
  void allot(std::size_t n) {
    std::vector<double> areas(leaves.size());
    std::vector<std::size_t> quotas(leaves.size(), 1), open;
    for (std::size_t i = 0; i < leaves.size(); ++i) {
      areas[i] = leaves[i].region.area;
      if (!leaves[i].final && !leaves[i].region.keep_whole) open.push_back(i);
    }
    allot_quotas(areas, quotas, open, n - std::min(n, leaves.size()));
    for (std::size_t i = 0; i < leaves.size(); ++i)
      if (!leaves[i].final) leaves[i].quota = quotas[i];
  }
  /// What orders the splits: the policy's priority, else the area (largest first).
  double split_key(std::size_t i) const { return by_policy ? priority[i] : leaves[i].region.area; }
  /// Whether leaf i still has to be split (by area: larger than the bound; by policy: a
  /// positive priority); never a region kept whole (a cap).
  bool wanted(std::size_t i, const madd_options& o) const {
    if (leaves[i].region.keep_whole) return false;
    if (by_policy) return priority[i] > 0.0;
    if (by_quota) return leaves[i].quota > 1;
    return leaves[i].region.area > o.max_subdomain_area;
  }
  /// The regions, moved out (the state is spent).
  std::vector<madd_region> regions() {
    std::vector<madd_region> out;
    for (auto& l : leaves)
      out.push_back(std::move(l.region));
    return out;
  }
};

/// The global refinement length h = L_a / (r sqrt N) of the static MADD (4.1); N is the
/// number asked for, or total area / max_subdomain_area.
inline double global_refinement_length(const madd_state& s, const madd_options& o) {
  double len = 0.0, total_area = 0.0;
  std::size_t n = 0;
  for (const auto& l : s.leaves) {
    len += region_perimeter(l.region);
    n += region_vertex_count(l.region);
    total_area += l.region.area;
  }
  const double target_n = s.by_area ? std::max(1.0, total_area / o.max_subdomain_area)
                                    : static_cast<double>(o.subdomains);
  return len / static_cast<double>(n) / (o.refinement_factor * std::sqrt(target_n));
}

/// The options of every split (target_length is set per region).
inline madd_split_options split_options_for(const madd_options& o) {
  madd_split_options so;
  so.graph.algorithm = o.algorithm;
  so.graph.phi0 = o.min_separator_angle_deg;
  so.graph.phi0_accept = o.min_separator_angle_deg + 1e-7;
  so.graph.smoothing = o.smoothing;
  so.max_levels = o.max_refinement_levels;
  so.max_encroachment_depth = o.max_encroachment_depth;
  so.imbalance_bound = o.imbalance_bound;
  so.max_part_fraction = o.max_part_fraction;
  so.feature_clearance = o.feature_clearance;
  return so;
}

/// \throws decomposition_error naming every leaf that could not be split and why.
[[noreturn]] inline void throw_unsplittable(const madd_state& s, const madd_options& o) {
  std::string msg =
      "MADD: cannot split the domain " +
      (s.by_policy ? std::string("as the split policy asks")
       : s.by_area ? "into subdomains of area <= " + std::to_string(o.max_subdomain_area)
                   : "into " + std::to_string(o.subdomains) + " subdomains") +
      " (reached " + std::to_string(s.leaves.size()) + ")";
  for (std::size_t i = 0; i < s.leaves.size(); ++i)
    if (s.leaves[i].final && s.wanted(i, o))
      msg += "; subdomain " + std::to_string(i) + " (area " +
             std::to_string(s.leaves[i].region.area) +
             (s.by_policy ? ", priority " + std::to_string(s.priority[i]) : std::string()) + ", " +
             std::to_string(region_vertex_count(s.leaves[i].region)) +
             " vertices): " + s.leaves[i].why;
  throw decomposition_error(msg);
}

/// Whether some leaf still has to be split.
inline bool any_wanted(const madd_state& s, const madd_options& o) {
  for (std::size_t i = 0; i < s.leaves.size(); ++i)
    if (s.wanted(i, o)) return true;
  return false;
}

/// The leaves to split in the next round (4.3), largest key first (the area, or the split
/// policy's priority; ties: lower index). Into N: the quotas are shared anew among the leaves
/// (so a child left larger than its share gets more: the partitioner's imbalance is corrected,
/// not compounded) and every leaf whose quota is above 1 is split. Otherwise only what a
/// sequential largest-first loop would split next, i.e. leaves of at least round_fraction
/// times the largest key (their children are smaller than that as long as splits are balanced
/// to round_fraction, so no child would be split before them). nullopt when the goal is
/// reached.
/// \throws decomposition_error when nothing can be split.
inline std::optional<std::vector<std::size_t>> next_round(madd_state& s, const madd_options& o) {
  s.update_priorities(o);
  if (s.by_quota) s.allot(o.subdomains);
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < s.leaves.size(); ++i)
    if (!s.leaves[i].final && s.wanted(i, o)) order.push_back(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return s.split_key(a) > s.split_key(b); });
  if (s.by_area ? order.empty() : s.leaves.size() >= o.subdomains) return std::nullopt;
  if (s.by_policy && !any_wanted(s, o)) return std::nullopt;
  if (order.empty()) throw_unsplittable(s, o);
  if (s.by_quota) return order;
  const double cut = o.round_fraction * s.split_key(order[0]);
  std::size_t take = 0;
  while (take < order.size() && s.split_key(order[take]) >= cut)
    ++take;
  if (s.by_policy) take = std::min(take, o.subdomains - s.leaves.size());
  order.resize(take);
  return order;
}

/// Adds one successful split to the statistics.
inline void record_split(const madd_split_result& r, decomposition_statistics& st) {
  ++st.splits;
  st.repairs += r.repairs;
  st.smoothing_moves += r.smoothing_moves;
  st.algorithm_fallbacks += r.fallback ? 1 : 0;
  st.chord_splits += r.chord ? 1 : 0;
  st.boundary_points += r.z_points;
  st.mean_split_fraction += r.max_fraction;
  st.max_split_fraction = std::max(st.max_split_fraction, r.max_fraction);
  if (st.splits_per_level.size() <= static_cast<std::size_t>(r.level))
    st.splits_per_level.resize(r.level + 1, 0);
  ++st.splits_per_level[r.level];
}

/// Replaces every split leaf by its children (in place, keeping the order), marks leaves whose
/// split failed final, and applies the boundary points the splits kept to the neighbours.
inline void apply_round(madd_state& s, const std::vector<std::size_t>& order,
                        std::vector<madd_split_result>& res, decomposition_statistics& st) {
  std::vector<int> split_of(s.leaves.size(), -1);
  for (std::size_t k = 0; k < order.size(); ++k)
    split_of[order[k]] = static_cast<int>(k);
  std::vector<madd_edge_split> kept;
  std::vector<madd_leaf> next;
  for (std::size_t i = 0; i < s.leaves.size(); ++i) {
    const int k = split_of[i];
    st.levels_tried += k >= 0 ? res[k].levels_tried : 0;
    if (k >= 0 && res[k].ok) {
      record_split(res[k], st);
      kept.insert(kept.end(), res[k].kept.begin(), res[k].kept.end());
      for (auto& c : res[k].children)
        next.push_back({std::move(c), false, {}, 1});
      continue;
    }
    next.push_back(std::move(s.leaves[i]));
    if (k >= 0) {
      next.back().final = true;
      next.back().why = res[k].failure;
      ++st.failed_splits;
    }
  }
  s.leaves = std::move(next);
  std::vector<madd_region> regions = s.regions();
  apply_edge_splits(regions, std::move(kept));
  for (std::size_t i = 0; i < regions.size(); ++i)
    s.leaves[i].region = std::move(regions[i]);
}

} // namespace pdd::detail
