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
#include <pdd/decoupling/tiny_features.hpp>
#include <pdd/decoupling/feature_driven_sizing.hpp>
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
  std::optional<std::vector<detail::vertex_gap_sample>> gaps; // found once, when needed
  while (out.rounds.size() < o.max_rounds &&
         out.rounds[out.chosen].over_refinement > o.target_over_refinement) {
    if (!regions) regions = &own.emplace(g);
    if (!gaps) gaps = detail::domain_vertex_gaps(g, *regions);
    std::size_t found = 0;
    const feature_driven_sizing driver =
        detail::tiny_feature_driver(*gaps, f, max_area, cap, slope, found);
    if (found == 0) break;
    gradation_report rep;
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
