/// \file gradation_control.hpp
/// pdd::gradation_controlled_decompose: the gradation-controlled domain decomposition
/// (dissertation 7.3, Algorithm 7.1, with Condition 3 of 7.6) on MADD's split policy hook.
#pragma once

#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/core/decomposition.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/errors.hpp>
#include <pdd/madd/decompose.hpp>
#include <pdd/madd/decomposition_statistics.hpp>
#include <pdd/madd/detail/gradation_control.hpp>
#include <pdd/madd/gradation_options.hpp>
#include <pdd/madd/madd_options.hpp>
#include <pdd/madd/madd_start.hpp>
#include <pdd/partition/default_partitioner.hpp>
#include <pdd/sizing/any_sizing.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace pdd {

/// The conditions of Algorithm 7.1 measured on a decomposition.
struct gradation_report {
  /// m(D_i), M(D_i) per subdomain: bounds of min(max_area, F) over its bounding box (m a true
  /// lower bound, pdd::sizing_range; the k_i of the graded path come from it).
  std::vector<sizing_bounds> bounds;
  /// Expected triangles per subdomain (Algorithm 7.2; the executor's order of work).
  std::vector<double> expected_triangles;
  double r1_max = 1.0;               ///< max over subdomains of M / m (Condition 1: <= R1)
  double r2_max = 1.0;               ///< max over separators of m_i / m_j (Condition 2: <= R2)
  std::size_t condition_1_unmet = 0; ///< subdomains with M > R1 m
  std::size_t condition_2_unmet = 0; ///< neighbour pairs with m_i > R2 m_j
  std::size_t condition_3_unmet = 0; ///< subdomains expecting more than T triangles
  /// max_subdomains was reached while some subdomain was still to be split.
  bool capped = false;
};

namespace detail {
/// The report of d from the measures of its subdomains (neighbours: d.interfaces).
inline gradation_report gradation_report_of(const decomposition& d,
                                            const std::vector<leaf_measure>& m,
                                            const gradation_options& o) {
  gradation_report rep;
  for (const leaf_measure& x : m) {
    rep.bounds.push_back({x.lo, x.hi});
    rep.expected_triangles.push_back(x.expected);
    if (std::isfinite(x.lo)) rep.r1_max = std::max(rep.r1_max, x.hi / x.lo);
  }
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (const interface_curve& c : d.interfaces)
    pairs.emplace_back(std::min(c.a, c.b), std::max(c.a, c.b));
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  for (const auto& pr : pairs) {
    const double a = m[pr.first].lo, b = m[pr.second].lo;
    if (std::isfinite(a) && std::isfinite(b)) rep.r2_max = std::max({rep.r2_max, a / b, b / a});
    if (a > o.r2 * b || b > o.r2 * a) ++rep.condition_2_unmet;
  }
  for (const unsigned f : failed_conditions(m, {}, o.r1, o.r2, o.max_subdomain_triangles)) {
    rep.condition_1_unmet += (f & fails_condition_1) != 0u ? 1 : 0;
    rep.condition_3_unmet += (f & fails_condition_3) != 0u ? 1 : 0;
  }
  return rep;
}

/// Subdomain s of d as loops of points.
inline std::vector<std::vector<point>> subdomain_points(const decomposition& d, std::size_t s) {
  std::vector<std::vector<point>> loops;
  for (const auto& loop : d.subdomains[s].loops) {
    loops.emplace_back();
    for (const index_t v : loop)
      loops.back().push_back(d.vertices[v]);
  }
  return loops;
}

/// A number for a message, in the shortest general format ("1e-09", "0.0001").
inline std::string general_number(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

/// "; Algorithm 7.1 still wanted: subdomain i (m .., M .., expected .., fails Condition ..)"
/// for the leaves the policy last wanted split (at most 8).
inline std::string describe_wanted(const gradation_policy_state& s) {
  std::string out = "; Algorithm 7.1 (R1 " + general_number(s.r1) + ", R2 " + general_number(s.r2) +
                    ") still wanted split:";
  std::size_t listed = 0;
  for (std::size_t i = 0; i < s.last_priority.size() && listed < 8; ++i) {
    if (!(s.last_priority[i] > 0.0)) continue;
    ++listed;
    const leaf_measure& m = s.last[i];
    out += " subdomain " + std::to_string(i) + " (m " + general_number(m.lo) + ", M " +
           general_number(m.hi) + ", " + general_number(m.expected) + " expected triangles";
    for (int c = 0; c < 3; ++c)
      if ((s.last_fail[i] >> c) & 1u) out += ", fails Condition " + std::to_string(c + 1);
    out += ")";
  }
  return out;
}
} // namespace detail

/// The gradation-controlled decomposition of g (Algorithm 7.1): starting from the whole
/// domain, the largest non-acceptable subdomain (size measured as expected triangles) is
/// split by MADD until every subdomain meets
///  - Condition 1: M(D_i) <= R1 m(D_i),
///  - Condition 2: m(D_i) <= R2 m(D_j) for neighbours D_i, D_j (both are non-acceptable
///    otherwise),
///  - Condition 3: at most T expected triangles (integral of 1 / (0.656 F)),
/// where m and M bound min(max_area, F) over the subdomain's bounding box (pdd::sizing_range:
/// m is a true lower bound, never a sample). A subdomain expecting fewer than
/// min_subdomain_triangles is not split for Conditions 1-2 (termination for fields no
/// decomposition makes acceptable: jumps of ratio > R2); while fewer than min_subdomains exist
/// every subdomain is split. Splits run in MADD's rounds (madd_options::round_fraction), so
/// the result is bitwise identical for every thread count.
/// Background meshes: m and M come from the nodes of the background triangles over the
/// subdomain's box (a true bound of the linearly interpolated field), so every subdomain has
/// them and the geometric-mean interpolation of 7.3 is not needed.
/// \param mo MADD's options; its subdomains is replaced by o.max_subdomains, its split_policy
/// by Algorithm 7.1's; max_subdomain_area must stay infinite.
/// \throws pdd::decomposition_error for bad options (check_gradation_options, MADD's), or when
/// a subdomain the algorithm still has to split cannot be split: the message names it with
/// its m, M, expected triangles and the conditions it fails.
/// Complexity: MADD's, plus per new subdomain one sizing_range and one constrained
/// triangulation, plus per round a hash of all subdomain edges.
/// `start`: the regions of the domain (pdd::madd_start), found once for several calls.
template <GraphPartitioner P = default_partitioner>
decomposition gradation_controlled_decompose(const madd_start& start, const any_sizing& field,
                                             const gradation_options& o, madd_options mo = {},
                                             const P& partitioner = {},
                                             gradation_report* report = nullptr,
                                             decomposition_statistics* stats = nullptr) {
  check_gradation_options(o);
  auto state = std::make_shared<detail::gradation_policy_state>();
  state->measure = {field, o.max_area, o.mean_area_fraction};
  state->measure.range_options = o.range;
  state->r1 = o.r1;
  state->r2 = o.r2;
  state->t = o.max_subdomain_triangles;
  state->min_triangles = o.min_subdomain_triangles;
  state->min_leaves = o.min_subdomains;
  mo.subdomains = o.max_subdomains;
  mo.split_policy = [state](std::span<const madd_leaf_view> leaves) { return (*state)(leaves); };
  decomposition d;
  try {
    d = decompose(start, mo, partitioner, stats);
  } catch (const decomposition_error& e) {
    if (state->last_priority.empty()) throw;
    throw decomposition_error(e.what() + detail::describe_wanted(*state));
  }
  if (report) {
    std::vector<detail::leaf_measure> m;
    for (std::size_t s = 0; s < d.subdomains.size(); ++s) {
      const auto loops = detail::subdomain_points(d, s);
      const auto it = state->last_index.find(state->key_of(loops.front(), 0.0));
      m.push_back(it != state->last_index.end() ? state->last[it->second] : state->measure(loops));
    }
    *report = detail::gradation_report_of(d, m, o);
    report->capped = d.subdomains.size() >= o.max_subdomains &&
                     std::any_of(state->last_priority.begin(), state->last_priority.end(),
                                 [](double p) { return p > 0.0; });
  }
  return d;
}

/// gradation_controlled_decompose on the regions of g (pdd::madd_start(g): validates g).
template <GraphPartitioner P = default_partitioner>
decomposition gradation_controlled_decompose(const pslg& g, const any_sizing& field,
                                             const gradation_options& o, madd_options mo = {},
                                             const P& partitioner = {},
                                             gradation_report* report = nullptr,
                                             decomposition_statistics* stats = nullptr) {
  check_gradation_options(o);
  return gradation_controlled_decompose(madd_start(g), field, o, std::move(mo), partitioner, report,
                                        stats);
}

} // namespace pdd
