/// \file run_plan.hpp
/// pdd::run_plan: the one decision of a run, made once from the domain and the options (which
/// path, how many subdomains, why), and the plans it turns into when a stage says so (the
/// geometric loop once more with a smaller cap; the whole domain). pdd::plan_run makes it;
/// pipeline/chain.hpp runs it.
#pragma once

#include <pdd/core/bbox.hpp>
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/madd/madd_options.hpp>
#include <pdd/madd/madd_start.hpp>
#include <pdd/pipeline/detail/domain_reading.hpp>
#include <pdd/pipeline/detail/path_plan.hpp>
#include <pdd/pipeline/detail/whole_domain.hpp>
#include <pdd/pipeline/options.hpp>
#include <pdd/sizing/mesh_size_estimate.hpp>
#include <pdd/sizing/sizing_range.hpp>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <utility>

namespace pdd {

/// The path a run takes.
enum class mesh_path {
  monolithic, ///< N = 1: the kernel on the whole domain
  uniform,    ///< one k (Theorem 15): decoupling.k_override or k_scale set
  graded,     ///< k_i per subdomain (Theorem 22) from the user's field or the uniform bound
  geometric,  ///< the decomposition graded towards tiny features (Algorithm 8.3's F on closed
              ///< loops; the faces' features on a general PSLG), then k_i (Theorem 22)
};

/// generate_statistics::path's name of a path.
constexpr const char* path_name(mesh_path p) noexcept {
  switch (p) {
  case mesh_path::monolithic:
    return "monolithic";
  case mesh_path::uniform:
    return "uniform";
  case mesh_path::graded:
    return "graded";
  case mesh_path::geometric:
    return "geometric";
  }
  return "";
}

/// What a run does, decided before any work (pdd::plan_run) and changed only by the plans that
/// pdd::whole_domain_plan and pdd::plan_after_path return.
struct run_plan {
  /// The path the run takes (monolithic by default: N = 1, the kernel on the whole domain).
  mesh_path path = mesh_path::monolithic;
  /// N asked of MADD (1: no decomposition). The geometric loop and Algorithm 7.1 may make more.
  std::size_t subdomains = 1;
  /// Algorithm 7.1 (gradation_controlled_decompose) makes the decomposition: a sizing field on
  /// the graded or geometric path.
  bool gradation_controlled = false;
  /// Not one of closed loops (Triangle's rule; decoupled from its faces or meshed whole).
  bool general_domain = false;
  /// options.subdomains == 0: the plan may fall back to the whole domain when decoupling would
  /// not pay (too many split points; a general domain MADD cannot split).
  bool automatic = false;
  /// A fallback made this plan (generate_statistics::monolithic_fallback).
  bool fallback = false;
  /// The geometric loop's cap on subdomains (pdd::detail::geometric_cap raises it to 4N) and
  /// whether this is the loop's second run (no third).
  std::size_t geometric_cap = 0;
  /// True in the plan of the geometric loop's second run, with half the cap (made by
  /// pdd::plan_after_path); a plan with it set is not retried again.
  bool geometric_retried = false;
  double area = 0.0;           ///< pdd::domain_area
  mesh_size_estimate estimate; ///< the triangles planned for (pdd::estimate_mesh_size)
  /// The criteria the decoupling path and the shields are built for: max_area lowered to the
  /// sizing field's minimum over the domain (the interim rule, generate_options::sizing).
  mesh_criteria decoupling_criteria;
  /// Why this path and N (generate_statistics::plan_reason before the stages add to it).
  std::string reason;
  /// The plan's reason before any retry (a retry's reason builds on it).
  std::string first_reason;
};

/// A domain read for a plan: validated, with Triangle's rule where it is not one of closed
/// loops, and the regions MADD starts from (none when one subdomain is asked for).
struct planned_run {
  /// The user's domain, validated; with domain_rule::triangle where it is not one of closed
  /// loops.
  pslg domain;
  /// The regions MADD starts from (pdd::madd_start), found once; empty when the plan asks for
  /// one subdomain.
  std::optional<madd_start> regions;
  /// The plan for the domain (pdd::plan_run).
  run_plan plan;
};

namespace detail {
/// The path of N > 1 subdomains on a domain of closed loops or not (`geometric`: chosen by
/// choose_geometric_path).
inline mesh_path decoupled_path(const generate_options& o, bool geometric) {
  if (geometric) return mesh_path::geometric;
  return o.decoupling.k_override > 0.0 || o.decoupling.k_scale != 1.0 ? mesh_path::uniform
                                                                      : mesh_path::graded;
}
} // namespace detail

/// The plan for meshing `domain` with options `o` on `threads` threads: validates the domain
/// once (detail::read_domain), estimates the mesh (pdd::estimate_mesh_size), takes N
/// (options.subdomains; 0: automatic_subdomains of the estimate when some area bound is given,
/// 1 without any; a general domain at least one per face) and the path: monolithic for N = 1,
/// geometric where detail::choose_geometric_path (detail::choose_face_geometric_path on a
/// general PSLG) says so, uniform where k is set, else graded.
/// \pre check_generate_options(o) passed. \throws pdd::geometry_error for an invalid domain;
/// pdd::sizing_error for a field that is not positive in the domain (read_domain).
/// Complexity: validation, the field's bounds and the estimate.
inline planned_run plan_run(pslg domain, const generate_options& o, unsigned threads) {
  planned_run r;
  run_plan& p = r.plan;
  detail::domain_reading read = detail::read_domain(domain, o);
  p.decoupling_criteria = o.criteria;
  p.decoupling_criteria.max_area = std::min(o.criteria.max_area, read.sizing_min);
  r.domain = std::move(domain);
  r.regions = std::move(read.start);
  p.general_domain = read.general;
  p.area = read.area;
  p.estimate = read.estimate;
  p.automatic = o.subdomains == 0;
  const detail::general_domain_plan general =
      p.general_domain ? detail::plan_general_domain(r.regions ? &*r.regions : nullptr)
                       : detail::general_domain_plan{};
  p.subdomains = detail::planned_subdomains(o, p.estimate.triangles, threads,
                                            p.general_domain ? &general : nullptr, p.reason);
  const bool geometric =
      p.general_domain
          ? detail::choose_face_geometric_path(r.regions ? &*r.regions : nullptr, o,
                                               p.decoupling_criteria.max_area, p.subdomains,
                                               p.estimate.triangles, p.reason)
          : detail::choose_geometric_path(r.domain, o, p.decoupling_criteria.max_area, p.subdomains,
                                          p.estimate.triangles, p.reason);
  if (p.subdomains > 1 && detail::small_angles_above_ruppert(r.domain, o.criteria, p.reason))
    p.subdomains = 1;
  p.path = p.subdomains <= 1 ? mesh_path::monolithic : detail::decoupled_path(o, geometric);
  p.gradation_controlled = o.sizing && p.subdomains > 1 && p.path != mesh_path::uniform;
  p.geometric_cap = o.geometric_loop.max_subdomains;
  p.first_reason = p.reason;
  return r;
}

/// The plan once a stage found that decoupling does not pay or cannot be done: the kernel on
/// the whole domain, for `why` (empty: the reason stays).
inline run_plan whole_domain_plan(run_plan p, std::string why) {
  p.path = mesh_path::monolithic;
  p.subdomains = 1;
  p.gradation_controlled = false;
  p.fallback = true;
  if (!why.empty()) p.reason = std::move(why);
  return p;
}

/// The plan after a decoupling path with `split_points` split points: none when it pays (at
/// most planning.max_split_point_fraction of the `estimated` triangles, or N given by the
/// user); on the geometric path, once, the loop again with half its last cap `cap` (the cap
/// trades the grading towards tiny features against separator length; on the Bahamas at 2M
/// triangles 4096 left 108K split points, 5.4 % of the estimate, 2048 left 95K) unless half is
/// below 4N or would not bind on the `made` subdomains; else the whole domain.
/// `reason`: the statistics' reason so far (the whole domain's reason extends it).
inline std::optional<run_plan> plan_after_path(const run_plan& p, std::size_t split_points,
                                               double estimated, std::size_t cap, std::size_t made,
                                               const std::string& reason,
                                               const planning_options& o) {
  if (!p.automatic || made <= 1 || p.path == mesh_path::monolithic ||
      !(static_cast<double>(split_points) > o.max_split_point_fraction * estimated))
    return std::nullopt;
  const std::size_t half = cap / 2;
  if (p.path == mesh_path::geometric && !p.geometric_retried && half >= 4 * p.subdomains &&
      made > half) {
    run_plan retry = p;
    retry.geometric_retried = true;
    retry.geometric_cap = half;
    retry.reason =
        p.first_reason + "; " + detail::geometric_retry_reason(split_points, cap, o, half);
    return retry;
  }
  return whole_domain_plan(p, (p.path == mesh_path::geometric ? reason + "; " : std::string()) +
                                  detail::split_point_reason(split_points, estimated, o));
}

} // namespace pdd
