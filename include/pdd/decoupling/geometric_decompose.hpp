/// \file geometric_decompose.hpp
/// pdd::geometric_decompose: decomposition and the sizing function built from the geometry,
/// iterated (issue 17 item 2): Algorithm 8.3 on a fixed decomposition shrinks F over a whole
/// subdomain that holds a tiny feature (and, by R2, its neighbours); the loop decomposes again,
/// graded towards such features (Algorithm 7.1), until the over-refinement F causes is small.
#pragma once

#include <pdd/concepts/executor.hpp>
#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/core/bbox.hpp>
#include <pdd/core/decomposition.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/decoupling/geometric_decompose_options.hpp>
#include <pdd/decoupling/geometric_sizing.hpp>
#include <pdd/geometry/feature_gap.hpp>
#include <pdd/madd/gradation_control.hpp>
#include <pdd/madd/gradation_options.hpp>
#include <pdd/madd/madd_options.hpp>
#include <pdd/madd/madd_start.hpp>
#include <pdd/parallel/sequential_executor.hpp>
#include <pdd/partition/default_partitioner.hpp>
#include <pdd/sizing/any_sizing.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <utility>
#include <vector>

namespace pdd {

/// One round of the loop.
struct geometric_round {
  /// N of the round's decomposition.
  std::size_t subdomains = 0;
  std::size_t features = 0;      ///< tiny-feature vertices the decomposition was graded towards
  double slope = 0.0;            ///< the driver's slope (0: the initial decomposition)
  double over_refinement = 0.0;  ///< estimated (geometric_sizing_result::over_refinement)
  double expected_triangles = 0; ///< under F
  bool capped = false;           ///< Algorithm 7.1 stopped at max_subdomains
};

/// The loop's result: the chosen round's decomposition and F, and every round.
struct geometric_decomposition {
  /// The chosen round's decomposition.
  decomposition parts;
  /// Algorithm 8.3 on `parts`: F's per-subdomain values (g_i, scales, expected triangles).
  geometric_sizing_result sizing;
  /// Every round run, in order (rounds[0]: the given decomposition); at most max_rounds.
  std::vector<geometric_round> rounds;
  std::size_t chosen = 0; ///< index in rounds of the decomposition returned
  std::size_t cap = 0;    ///< the cap on subdomains the refined rounds ran under
};

/// The driving field of a refined round: min(max_area, f(x), min over tiny-feature vertices v
/// of 4 sqrt2 (gap(v)/2 + slope |x - v|)^2), the area bound (relation 8.12 with e = lfs) of a
/// feature size growing by `slope` per unit of distance from v. Why slope < 1 (lfs itself is
/// 1-Lipschitz): Algorithm 7.1 makes subdomains a fixed fraction of their distance from v, and
/// Algorithm 8.3 bounds F by lfs_min(D_i), which the subdomain's own size bounds; where the
/// driver reaches f the subdomains must already be several mesh edges wide, or F stays below
/// f there and the R2 propagation carries that far out. A smaller slope reaches f farther out.
/// range(box) is exact for the distance term (nearest and farthest point of the box from v)
/// and f's own range otherwise. It only shapes the decomposition; F's guarantees come from
/// Algorithm 8.3 with the exact lfs_min(D_i). Thread-safety: const and shared.
class feature_driven_sizing {
public:
  /// \pre slope >= 0, half_gap[i] >= 0.
  feature_driven_sizing(any_sizing base, double max_area, std::vector<point> at,
                        std::vector<double> half_gap, double slope)
      : data_(sorted_by_x(
            data{std::move(base), max_area, std::move(at), std::move(half_gap), slope})) {}
  /// min(max_area, f(p), bound(i, |p - v_i|) over i), measuring only the features that can
  /// beat the minimum so far: bound grows with e = gap/2 + slope * distance, so a feature
  /// counts only where e is below the current minimum's (`reach`, compared squared, with a
  /// relative margin of 1e-9 that only ever measures more), which also bounds |x - v_i.x|: the
  /// features are sorted by x and those of the slab are read. The result is the plain minimum
  /// over all features. This is the hot path of Algorithm 7.1 with hundreds of tiny features
  /// (on the Bahamas it was half of a whole pdd-mesh run).
  double area_at(const point& p) const {
    const data& d = *data_;
    double best = std::min(d.max_area, d.base.area_at(p));
    double reach = reach_of(best);
    if (!(d.min_half_gap < reach)) return best;
    const double half_width = (reach - d.min_half_gap) / d.slope; // +inf for slope 0
    const auto by_x = [](const point& a, double x) { return a.x < x; };
    const auto first = std::lower_bound(d.at.begin(), d.at.end(), p.x - half_width, by_x);
    for (auto it = first; it != d.at.end() && it->x <= p.x + half_width; ++it) {
      const auto i = static_cast<std::size_t>(it - d.at.begin());
      const double within = reach - d.half_gap[i];
      if (!(within > 0.0)) continue;
      const double dx = p.x - it->x;
      const double dy = p.y - it->y;
      const double squared = dx * dx + dy * dy;
      if (d.slope * d.slope * squared > within * within) continue;
      const double b = bound(i, std::sqrt(squared));
      if (b < best) {
        best = b;
        reach = reach_of(best);
      }
    }
    return best;
  }
  /// Bounds over the closed box b: min(max_area, f)'s range, and per feature the driver's
  /// bound at the nearest (lo) and farthest (hi) point of the box from it (see the class
  /// comment).
  sizing_bounds range(const bbox& b) const { return with_features(data_->base.range(b), b); }
  /// Bounds over the closed region r: f's over the region (evaluated only there), the
  /// features' over its box.
  sizing_bounds range(const sizing_region& r, const sizing_range_options& o) const {
    return with_features(data_->base.range(r, o), r.box());
  }
  /// "feature_driven": the field's name in reports (any_sizing::kind, min_sizing::kind).
  static constexpr const char* kind() noexcept { return "feature_driven"; }

private:
  /// f's bounds `r` capped by max_area and by each feature's bound over box b.
  sizing_bounds with_features(sizing_bounds r, const bbox& b) const {
    r = {std::min(r.lo, data_->max_area), std::min(r.hi, data_->max_area)};
    for (std::size_t i = 0; i < data_->at.size(); ++i) {
      const point q = data_->at[i];
      const double dx = std::max({b.xmin - q.x, 0.0, q.x - b.xmax});
      const double dy = std::max({b.ymin - q.y, 0.0, q.y - b.ymax});
      const double fx = std::max(std::abs(q.x - b.xmin), std::abs(q.x - b.xmax));
      const double fy = std::max(std::abs(q.y - b.ymin), std::abs(q.y - b.ymax));
      r.lo = std::min(r.lo, bound(i, std::hypot(dx, dy)));
      r.hi = std::min(r.hi, bound(i, std::hypot(fx, fy)));
    }
    return r;
  }

  /// The e = gap/2 + slope * distance at which bound reaches `area`, slightly enlarged.
  static double reach_of(double area) {
    return std::sqrt(area / (4.0 * std::numbers::sqrt2)) * (1.0 + 1e-9);
  }
  /// 4 sqrt2 e^2 with e = gap(v_i)/2 + slope * distance.
  double bound(std::size_t i, double distance) const {
    const double e = data_->half_gap[i] + data_->slope * distance;
    return 4.0 * std::numbers::sqrt2 * e * e;
  }
  struct data {
    any_sizing base;
    double max_area;
    std::vector<point> at;
    std::vector<double> half_gap;
    double slope;
    double min_half_gap = std::numeric_limits<double>::infinity();
  };
  /// Sorted by x (then y): area_at reads the slab of features near p's x.
  static std::shared_ptr<const data> sorted_by_x(data in) {
    std::vector<std::size_t> order(in.at.size());
    for (std::size_t i = 0; i < order.size(); ++i)
      order[i] = i;
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return std::pair(in.at[a].x, in.at[a].y) < std::pair(in.at[b].x, in.at[b].y);
    });
    auto out = std::make_shared<data>(data{std::move(in.base),
                                           in.max_area,
                                           {},
                                           {},
                                           in.slope,
                                           std::numeric_limits<double>::infinity()});
    for (const std::size_t i : order) {
      out->at.push_back(in.at[i]);
      out->half_gap.push_back(in.half_gap[i]);
      out->min_half_gap = std::min(out->min_half_gap, in.half_gap[i]);
    }
    return out;
  }
  std::shared_ptr<const data> data_;
};

namespace detail {
/// The input vertices whose own feature bound 4 sqrt2 (gap/2)^2 lies below min(max_area, f)
/// there (a feature smaller than the mesh), the `cap` most binding first (ratio, then id).
inline feature_driven_sizing tiny_feature_driver(const pslg& g, const any_sizing& f,
                                                 double max_area, std::size_t cap, double slope,
                                                 std::size_t& found) {
  const feature_gap_field gaps(g);
  std::vector<std::pair<double, index_t>> binding;
  for (index_t v = 0; v < g.vertices.size(); ++v) {
    const double gap = gaps.vertex_gap(v);
    if (!std::isfinite(gap) || !(gap > 0.0)) continue;
    const double own = std::numbers::sqrt2 * gap * gap; // 4 sqrt2 (gap / 2)^2
    const double user = std::min(max_area, f.area_at(g.vertices[v]));
    if (own < user) binding.emplace_back(own / user, v);
  }
  std::sort(binding.begin(), binding.end());
  binding.resize(std::min(binding.size(), cap));
  found = binding.size();
  std::vector<point> at;
  std::vector<double> half_gap;
  for (const auto& [ratio, v] : binding) {
    at.push_back(g.vertices[v]);
    half_gap.push_back(gaps.vertex_gap(v) / 2.0);
  }
  return {f, max_area, std::move(at), std::move(half_gap), slope};
}
} // namespace detail

/// The loop of decomposition and Algorithm 8.3 (issue 17 item 2), starting from `initial` (the
/// pipeline's decomposition: N-way MADD, or Algorithm 7.1 for a field):
///  round 1: F = Algorithm 8.3 on `initial` (pdd::geometric_sizing); its over-refinement is
///    the integral of 1 / (0.656 F) over that of 1 / (0.656 f), minus 1;
///  while it exceeds o.target_over_refinement and rounds remain: the domain is decomposed
///    again by Algorithm 7.1 (pdd::gradation_controlled_decompose, at least `go.min_subdomains`
///    subdomains, at most o.max_subdomains, no termination minimum) driven by
///    pdd::feature_driven_sizing over the tiny features (cap: o.first_feature_cap, x8 per
///    round; slope o.first_slope, / 4 per round): subdomains grow with the distance from each
///    tiny feature, so the feature's own small F stays in a small subdomain and the R2 steps
///    of Algorithm 8.3 fit the grading; each round grades more slowly (more, larger
///    subdomains where the driver meets f); then Algorithm 8.3 again. A round that reached
///    o.max_subdomains ends the loop (a slower grading needs still more subdomains).
/// The round with the fewest expected triangles under F is returned (rounds lists all).
/// \param regions g's regions (pdd::madd_start) when the caller has them; else found here once.
/// \param go Algorithm 7.1's options as the pipeline sets them (R1, R2, T, min_subdomains);
/// max_area, min_subdomain_triangles and max_subdomains are set here.
/// \throws as pdd::geometric_sizing and pdd::gradation_controlled_decompose.
/// Deterministic for every executor and thread count.
template <GraphPartitioner P = default_partitioner, Executor E = sequential_executor>
geometric_decomposition
geometric_decompose(const pslg& g, decomposition initial, const any_sizing& f, double max_area,
                    gradation_options go, const madd_options& mo,
                    const geometric_decompose_options& o = {}, const P& partitioner = {},
                    const E& executor = {}, const madd_start* regions = nullptr) {
  geometric_decomposition out;
  out.sizing = geometric_sizing(initial, f, max_area, go.r2, executor);
  out.parts = std::move(initial);
  out.rounds.push_back({out.parts.subdomains.size(), 0, 0.0, out.sizing.over_refinement(),
                        out.sizing.expected_triangles_F(), false});
  std::size_t cap = o.first_feature_cap;
  double slope = o.first_slope;
  go.max_area = max_area;
  go.min_subdomain_triangles = 0.0; // the driver is continuous: 7.1 terminates (Lemma 17)
  go.max_subdomains = std::max(o.max_subdomains, go.min_subdomains);
  out.cap = go.max_subdomains;
  std::optional<madd_start> own; // g's regions, found once for every round (unless given)
  while (out.rounds.size() < o.max_rounds &&
         out.rounds[out.chosen].over_refinement > o.target_over_refinement) {
    std::size_t found = 0;
    const feature_driven_sizing driver =
        detail::tiny_feature_driver(g, f, max_area, cap, slope, found);
    if (found == 0) break;
    gradation_report rep;
    if (!regions) regions = &own.emplace(g);
    decomposition d = gradation_controlled_decompose(*regions, driver, go, mo, partitioner, &rep);
    geometric_sizing_result s = geometric_sizing(d, f, max_area, go.r2, executor);
    out.rounds.push_back({d.subdomains.size(), found, slope, s.over_refinement(),
                          s.expected_triangles_F(), rep.capped});
    cap *= 8;
    slope /= 4.0;
    if (out.rounds.back().expected_triangles < out.rounds[out.chosen].expected_triangles) {
      out.chosen = out.rounds.size() - 1;
      out.parts = std::move(d);
      out.sizing = std::move(s);
    }
    if (out.rounds.back().capped) break;
  }
  return out;
}

} // namespace pdd
