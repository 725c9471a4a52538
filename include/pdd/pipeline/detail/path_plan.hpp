/// \file path_plan.hpp
/// The pipeline's choice of path (monolithic, uniform, graded, geometric) and the geometric
/// path's stage: the loop of decomposition and Algorithm 8.3 (pdd::geometric_decompose) on
/// the pipeline's options, and what it records.
#pragma once

#include <pdd/concepts/executor.hpp>
#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/core/decomposition.hpp>
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/decoupling/geometric_decompose.hpp>
#include <pdd/decoupling/tiny_features.hpp>
#include <pdd/geometry/lfs.hpp>
#include <pdd/madd/gradation_control.hpp>
#include <pdd/madd/madd_options.hpp>
#include <pdd/madd/madd_start.hpp>
#include <pdd/pipeline/options.hpp>
#include <pdd/pipeline/statistics.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <utility>

namespace pdd::detail {

inline std::string number_text(double v) {
  std::ostringstream out;
  out << v;
  return out.str();
}

/// The plan's reason for one subdomain on a domain that is not one of closed loops.
inline constexpr const char* general_domain_reason =
    "one subdomain: the domain is not one of closed loops (internal or dangling segments, "
    "isolated vertices, touching loops or internal boundaries), the kernel meshes it whole";

/// The plan's reason for falling back to N = 1 on too many split points.
inline std::string split_point_reason(std::size_t split_points, double estimated,
                                      const planning_options& p) {
  return std::to_string(split_points) + " split points on the separators, more than " +
         number_text(100.0 * p.max_split_point_fraction) + " % of the " + number_text(estimated) +
         " estimated triangles (planning.max_split_point_fraction): decoupling would not pay, "
         "one subdomain";
}

/// The plan's reason for the geometric loop's second run: `split_points` with a cap of `cap`
/// subdomains, again with a cap of `next`.
inline std::string geometric_retry_reason(std::size_t split_points, std::size_t cap,
                                          const planning_options& p, std::size_t next) {
  return std::to_string(split_points) + " split points with the loop's cap of " +
         std::to_string(cap) + " subdomains, more than " +
         number_text(100.0 * p.max_split_point_fraction) +
         " % of the estimate: MADD and the loop again with a cap of " + std::to_string(next);
}

/// Whether the geometric path is planned (generate_options::geometric_sizing) for N =
/// `subdomains` and `estimated` triangles; writes the reason. `area_min` is the smallest area
/// bound over the domain (min of criteria.max_area and the field's lower bound).
inline bool choose_geometric_path(const pslg& domain, const generate_options& o, double area_min,
                                  std::size_t subdomains, double estimated, std::string& reason) {
  const auto no = [&](const std::string& why) {
    reason = why;
    return false;
  };
  if (subdomains <= 1)
    return no(o.subdomains == 1 ? "one subdomain requested"
              : std::isfinite(area_min)
                  ? "estimated " + number_text(estimated) +
                        " triangles: too few to decompose (pdd::automatic_subdomains)"
                  : "no area bound: the kernel meshes the domain graded by its geometry");
  if (o.geometric_sizing == geometric_sizing_mode::off) return no("geometric sizing off");
  if (o.decoupling.k_override > 0.0 || o.decoupling.k_scale != 1.0)
    return no("decoupling.k_override or k_scale set: the uniform path");
  if (!std::isfinite(area_min)) return no("no area bound: Algorithm 8.3 scales a bounded field");
  if (!o.criteria.within_ruppert_bound())
    return no("an angle bound above 20.7 deg: the kernels split the path beside the small "
              "subdomains of tiny features there (the Bahamas at 25-30 deg, --max-area 1e-5)");
  if (o.geometric_sizing == geometric_sizing_mode::on) return !no("geometric sizing on");
  // automatic: the uniform --max-area with automatic N (a field or a requested N keep their
  // graded or uniform path unless geometric sizing is on)
  if (o.sizing)
    return no("a sizing field: the graded path (geometric sizing auto needs a uniform bound)");
  if (o.subdomains != 0) return no("a requested N: geometric sizing auto plans automatic N only");
  const double lfs = lfs_min(domain), term = 0.5 * std::sqrt(area_min / std::numbers::sqrt2);
  const std::string numbers =
      "lfs_min " + number_text(lfs) + ", (1/2) sqrt(m / sqrt2) " + number_text(term);
  if (!(lfs < term)) return no("no feature smaller than the mesh (" + numbers + ")");
  return !no("a feature smaller than the mesh (" + numbers + "): Algorithm 8.3");
}

/// Whether the geometric path on a general PSLG is planned under criteria c: only up to
/// Ruppert's bound (circumradius-to-shortest-edge ratio at least sqrt 2, 20.7 deg), under which
/// the decoupling theorems hold. Above it the path is kept only where the kernels never split
/// it in practice, and on the small subdomains this path makes beside tiny features they did:
/// la.poly --subdomains 4 at 28 deg (--max-area 0.01) and 30 deg (0.003, 0.001) ran out of
/// invariance repairs, where MADD from the faces meshes.
inline bool face_path_angle_ok(const mesh_criteria& c) {
  return c.within_ruppert_bound();
}

/// Whether the geometric path is planned on a domain that is not one of closed loops, with
/// regions `regions` (pdd::madd_start), for N = `subdomains`, `area_min` as above and `estimated`
/// triangles; appends the reason to `reason` (which says already why N); only where
/// face_path_angle_ok. Unlike on closed loops, geometric sizing auto plans it for a requested N
/// too: the faces are subdomains whatever N, so a small feature of a face sets k_i of that face
/// and of its neighbours (relation 7.1) along every interface unless the decomposition is graded
/// towards it (detail::face_geometric_decompose). Auto needs planning.min_face_path_triangles
/// and features of the faces smaller than the mesh (under min(max_area, field);
/// binding_features), but not more than a tenth of the faces' vertices (at least
/// geometric_loop.first_feature_cap): where more bind, the boundary itself is finer than the
/// mesh (a wavy ring of 200K segments, benchmarks/run_general_planning.sh: 13.6 s of rounds,
/// none cheaper than MADD's own decomposition).
inline bool choose_face_geometric_path(const madd_start* regions, const generate_options& o,
                                       double area_min, std::size_t subdomains, double estimated,
                                       std::string& reason) {
  const auto no = [&](const std::string& why) {
    reason += "; not the geometric path: " + why;
    return false;
  };
  if (subdomains <= 1 || !regions) return false; // the reason says why one subdomain
  if (o.geometric_sizing == geometric_sizing_mode::off) return no("geometric sizing off");
  if (o.decoupling.k_override > 0.0 || o.decoupling.k_scale != 1.0)
    return no("decoupling.k_override or k_scale set: the uniform path");
  if (!std::isfinite(area_min)) return no("no area bound");
  if (!face_path_angle_ok(o.criteria))
    return no("an angle bound above 20.7 deg (the kernels split the path beside tiny features "
              "there)");
  if (o.geometric_sizing == geometric_sizing_mode::on) {
    reason += "; geometric sizing on";
    return true;
  }
  if (!(estimated >= o.planning.min_face_path_triangles))
    return no("estimated " + number_text(estimated) + " triangles, under " +
              number_text(o.planning.min_face_path_triangles) +
              " (planning.min_face_path_triangles): its rounds would cost more than they save");
  const std::vector<vertex_gap_sample> gaps = region_vertex_gaps(*regions);
  const std::size_t found = binding_features(gaps, o.sizing, area_min).size();
  if (found == 0) return no("no feature of a face is smaller than the mesh");
  const auto most = std::max<std::size_t>(o.geometric_loop.first_feature_cap, gaps.size() / 10);
  if (found > most)
    return no(std::to_string(found) + " of the faces' " + std::to_string(gaps.size()) +
              " vertices are features smaller than the mesh (more than " + std::to_string(most) +
              "): a boundary finer than the mesh, which the rounds cannot grade towards");
  reason += "; " + std::to_string(found) +
            " feature(s) of the faces smaller than the mesh: the geometric path on the faces";
  return true;
}

/// The geometric loop's cap on subdomains for a plan of n: the plan's `cap`, at least 4n.
inline std::size_t geometric_cap(std::size_t cap, std::size_t n) {
  return std::max<std::size_t>(cap, 4 * n);
}

/// The geometric path's decomposition: pdd::geometric_decompose from `initial` with
/// Algorithm 7.1's options as the pipeline sets them (R1, R2 of o.gradation; at least n
/// subdomains; Condition 3 T = target_subdomain_triangles for automatic N), the loop capped
/// at geometric_cap(cap, n).
template <GraphPartitioner P, Executor E>
geometric_decomposition run_geometric(const pslg& domain, decomposition initial,
                                      const generate_options& o, std::size_t n, std::size_t cap,
                                      const madd_options& mo, const P& partitioner,
                                      const E& executor, const madd_start* regions) {
  gradation_options go = o.gradation;
  go.min_subdomains = n;
  if (o.subdomains == 0) go.max_subdomain_triangles = o.planning.target_subdomain_triangles;
  geometric_decompose_options gdo = o.geometric_loop;
  gdo.max_subdomains = geometric_cap(cap, n);
  return geometric_decompose(domain, std::move(initial), o.sizing, o.criteria.max_area, go, mo, gdo,
                             partitioner, executor, regions);
}

/// Records the loop in the statistics and the gradation report. With Algorithm 8.3's F
/// (o.geometric_field): m_F(D_i) = g_i, M_F(D_i) and the expected triangles under F for the
/// executor's order, the estimate scaled by the chosen round's over-refinement; returns true
/// when the plan should fall back to N = 1 (automatic N and over-refinement above
/// o.max_geometric_over_refinement). With the user's field: the expected triangles under f
/// only (the bounds then come from f itself); false (the split points decide, later).
inline bool record_geometric(const geometric_decomposition& gd, const generate_options& o,
                             generate_statistics& st, gradation_report& rep) {
  st.sizing_rounds = gd.rounds.size();
  st.sizing_round_used = gd.chosen;
  st.geometric_cap = gd.cap;
  st.estimated_over_refinement.clear();
  for (const geometric_round& r : gd.rounds)
    st.estimated_over_refinement.push_back(r.over_refinement);
  const double rho = gd.rounds[gd.chosen].over_refinement;
  const bool with_f = o.geometric_field == geometric_mesh_field::user;
  rep = {};
  for (std::size_t s = 0; s < gd.sizing.g.size(); ++s) {
    if (!with_f) rep.bounds.push_back(gd.sizing.field->piece_bounds(s));
    rep.expected_triangles.push_back(gd.sizing.expected_f[s] / (with_f ? 1.0 : gd.sizing.scale(s)));
  }
  st.plan_reason += "; " + std::to_string(gd.rounds.size()) + " round(s), Algorithm 8.3's " +
                    "estimated over-refinement " + number_text(100.0 * rho) + " %";
  if (with_f) {
    st.plan_reason += "; meshed with the user's field (k_i <= lfs_min(D_i))";
    return false;
  }
  if (o.subdomains != 0 || !(rho > o.max_geometric_over_refinement)) {
    st.estimated_triangles *= 1.0 + rho; // the plan's size check counts F's triangles
    return false;
  }
  st.plan_reason += " > " + number_text(100.0 * o.max_geometric_over_refinement) +
                    " %: decoupling would not pay, one subdomain";
  return true;
}

} // namespace pdd::detail
