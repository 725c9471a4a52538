/// \file face_path.hpp
/// The geometric path on a domain that is not one of closed loops (issue 36 item 1): its faces
/// are subdomains whatever N, and a small feature of a face (a layer that thins out, a pinch
/// between two interfaces) would set k_i of the whole face, so that every interface of it is
/// cut into pieces of that size (Triangle's la.poly at --max-area 0.01: 12,720 split points,
/// +79 % triangles). Rounds of Algorithm 7.1 driven towards the tiny features of the faces
/// (pdd::feature_driven_sizing, as the geometric loop on closed loops) make the subdomains near
/// them small, so that k_i is small only beside them; each round is judged by what it costs,
/// the triangles the split points of its graded path are estimated to add, and the cheapest
/// round (the faces' own decomposition among them) is taken.
#pragma once

#include <pdd/concepts/executor.hpp>
#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/core/decomposition.hpp>
#include <pdd/decoupling/feature_driven_sizing.hpp>
#include <pdd/decoupling/tiny_features.hpp>
#include <pdd/errors.hpp>
#include <pdd/madd/gradation_control.hpp>
#include <pdd/madd/madd_options.hpp>
#include <pdd/madd/madd_start.hpp>
#include <pdd/pipeline/detail/graded_path.hpp>
#include <pdd/pipeline/detail/path_plan.hpp>
#include <pdd/pipeline/options.hpp>
#include <pdd/sizing/any_sizing.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace pdd::detail {

/// What the graded path on a decomposition costs: its split points, and the triangles they
/// are estimated to add over the whole-domain mesh (path_cost).
struct face_path_cost {
  std::size_t split_points = 0;
  double extra_triangles = 0.0;
};

/// One round of the geometric path on a general PSLG.
struct face_round {
  std::size_t subdomains = 0;
  std::size_t features = 0; ///< tiny features the round was graded towards (0: MADD's own)
  double slope = 0.0;       ///< the driver's slope (0: MADD's own decomposition)
  /// The graded path's cost on it; nullopt where the path cannot be built.
  std::optional<face_path_cost> cost;
  bool capped = false; ///< Algorithm 7.1 stopped at its cap on subdomains
};

/// The rounds and the decomposition of the cheapest.
struct face_path_result {
  decomposition parts;
  std::vector<face_round> rounds;
  std::size_t chosen = 0;
  /// Why the rounds stopped early, when Algorithm 7.1 could not run (empty otherwise).
  std::string stopped;
};

/// The triangles the split points of path edge `e` of `dd` are estimated to add:
/// (pieces - 1) sqrt(h / l), l = |e| / pieces the piece length and h = sqrt(4 a / sqrt 3) the
/// edge of an equilateral triangle of area a = min(max_area, field) at the edge's midpoint (the
/// whole-domain mesh's size there). An empirical rule, only to rank decompositions: a piece
/// much shorter than the mesh forces small triangles that grade out around it. Fitted on
/// Triangle's la.poly at --max-area 0.01 and 0.001 (pieces 1.6x to 28x shorter than h:
/// 0.9 to 4.5 triangles per split point measured, the rule gives 1.0 to 4.2 with its factor
/// 0.8).
inline double path_edge_cost(const decoupled_decomposition& dd, const path_edge& e,
                             const any_sizing& field, double max_area) {
  if (e.pieces <= 1) return 0.0;
  const point a = dd.parts.vertices[e.u], b = dd.parts.vertices[e.v];
  const point mid{0.5 * (a.x + b.x), 0.5 * (a.y + b.y)};
  const double area = std::min(max_area, field ? field.area_at(mid) : max_area);
  const double h = std::sqrt(4.0 * area / std::sqrt(3.0));
  const double piece = e.length / static_cast<double>(e.pieces);
  if (!std::isfinite(h)) return 0.0; // no area bound: nothing to compare with
  return 0.8 * static_cast<double>(e.pieces - 1) * std::sqrt(std::max(1.0, h / piece));
}

/// The cost of the graded path (shields, then pdd::decouple_graded) on a copy of d, with k_i
/// from the minima of min(max_area, field) over each subdomain; nullopt where the path cannot
/// be built (pdd::decoupling_error, or pdd::geometry_error from the shields: a round is then
/// not taken, and MADD's own decomposition meshes as it did before this path).
template <Executor E>
std::optional<face_path_cost> graded_path_cost(decomposition d, const mesh_criteria& criteria,
                                               const any_sizing& field, const E& executor) {
  const std::vector<double> lo =
      subdomain_area_bounds(gradation_report{}, d, field, criteria.max_area, executor);
  try {
    const decoupled_decomposition dd = build_graded_path(d, criteria, lo, executor).graded.path;
    face_path_cost c{dd.points.size(), 0.0};
    for (const path_edge& e : dd.path)
      c.extra_triangles += path_edge_cost(dd, e, field, criteria.max_area);
    return c;
  } catch (const decoupling_error&) {
    return std::nullopt;
  } catch (const geometry_error&) { // the shields of a subdomain the round's decomposition
    return std::nullopt;            // pinches (fuzz: "duplicate vertices 1 and 4")
  }
}

/// Whether round `r` is estimated to add fewer triangles than round `best`.
inline bool cheaper(const face_round& r, const face_round& best) {
  return r.cost && (!best.cost || r.cost->extra_triangles < best.cost->extra_triangles);
}

/// R1 = R2 of Algorithm 7.1 in the rounds of the geometric path on a general PSLG. The driver
/// only shapes the decomposition (pdd::decouple_graded checks relation 7.1 on every separator
/// and lowers k where it must), and R2 just below 7.4's bound 3 (k_j / k_i < sqrt 3) lets the
/// subdomains grow fastest away from a feature: fewer, larger subdomains and fewer split
/// points. Measured against 1.425 / 1.5 (o.gradation's defaults), --subdomains 4: la.poly
/// 742,025 -> 736,572 triangles at --max-area 0.001 (whole domain 731,278), 84,183 -> 81,859 at
/// 0.01 (73,491); a pinching wedge (tests/pipeline/face_path_test.cpp) 135,308 -> 130,065 at
/// 0.001 (122,033).
inline constexpr double face_driver_gradation = 2.9;

/// The geometric path's decomposition of a general PSLG: round 0 is `initial` (MADD from the
/// faces); each further round is Algorithm 7.1 (at least n subdomains, at most
/// geometric_cap(cap, n); R1 = R2 = face_driver_gradation; Condition 3 T =
/// target_subdomain_triangles for automatic N) driven by pdd::feature_driven_sizing over the faces'
/// tiny features (detail::region_vertex_gaps; o.geometric_loop's first cap and slope, the cap x8
/// and the slope / 4 per round, at most max_rounds rounds in all); the round whose graded path is
/// estimated to add the fewest triangles (path_edge_cost) is returned. Stops early when no
/// feature binds, a round is capped, or Algorithm 7.1 throws pdd::geometry_error (it cannot
/// measure a subdomain whose loops touch at a vertex; `stopped` says so).
/// \throws as pdd::gradation_controlled_decompose. Deterministic for every executor.
template <GraphPartitioner P, Executor E>
face_path_result face_geometric_decompose(decomposition initial, const generate_options& o,
                                          std::size_t n, std::size_t cap, const madd_options& mo,
                                          const P& partitioner, const E& executor,
                                          const madd_start& regions) {
  face_path_result out;
  out.rounds.push_back({initial.subdomains.size(), 0, 0.0,
                        graded_path_cost(initial, o.criteria, o.sizing, executor), false});
  out.parts = std::move(initial);
  gradation_options go = o.gradation;
  go.r1 = go.r2 = face_driver_gradation;
  go.min_subdomains = n;
  if (o.subdomains == 0) go.max_subdomain_triangles = o.planning.target_subdomain_triangles;
  go.max_area = o.criteria.max_area;
  go.min_subdomain_triangles = 0.0; // the driver is continuous: 7.1 terminates (Lemma 17)
  go.max_subdomains = geometric_cap(cap, n);
  const std::vector<vertex_gap_sample> gaps = region_vertex_gaps(regions);
  std::size_t features = o.geometric_loop.first_feature_cap;
  double slope = o.geometric_loop.first_slope;
  while (out.rounds.size() < o.geometric_loop.max_rounds) {
    std::size_t found = 0;
    const feature_driven_sizing driver =
        tiny_feature_driver(gaps, o.sizing, o.criteria.max_area, features, slope, found);
    if (found == 0) break;
    gradation_report rep;
    decomposition d;
    try {
      d = gradation_controlled_decompose(regions, driver, go, mo, partitioner, &rep);
    } catch (const geometry_error& e) { // a leaf Algorithm 7.1 cannot measure (a pinched face)
      out.stopped = e.what();
      break;
    }
    out.rounds.push_back({d.subdomains.size(), found, slope,
                          graded_path_cost(d, o.criteria, o.sizing, executor), rep.capped});
    if (cheaper(out.rounds.back(), out.rounds[out.chosen])) {
      out.chosen = out.rounds.size() - 1;
      out.parts = std::move(d);
    }
    if (rep.capped) break;
    features *= 8;
    slope /= 4.0;
  }
  return out;
}

/// "; geometric path on the faces: round 0 (MADD, N 11) 13393 split points, about 57000
/// triangles more, round 1 (...) ...; round r taken", and what happens to Algorithm 8.3's F
/// when it was asked for.
inline std::string face_path_reason(const face_path_result& r, const generate_options& o) {
  std::string out = "; geometric path on the faces (Algorithm 7.1 towards their tiny features):";
  for (std::size_t i = 0; i < r.rounds.size(); ++i) {
    const face_round& x = r.rounds[i];
    out += (i ? ", round " : " round ") + std::to_string(i) +
           (i ? " (" + std::to_string(x.features) + " features, slope " + number_text(x.slope)
              : std::string(" (MADD")) +
           ", N " + std::to_string(x.subdomains) + (x.capped ? ", capped" : "") + ") " +
           (x.cost ? std::to_string(x.cost->split_points) + " split points, about " +
                         number_text(std::round(x.cost->extra_triangles)) + " triangles more"
                   : "no path");
  }
  if (!r.stopped.empty()) out += "; no further round: Algorithm 7.1 stopped: " + r.stopped;
  out += "; round " + std::to_string(r.chosen) + " taken, the fewest estimated more";
  if (o.geometric_field == geometric_mesh_field::algorithm_8_3)
    out += "; meshed with the user's field: Algorithm 8.3's F is built on domains of closed "
           "loops only";
  return out;
}

} // namespace pdd::detail
