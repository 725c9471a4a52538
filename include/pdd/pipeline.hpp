/// \file pipeline.hpp
/// pdd::pipeline: the stepwise uniform decoupling pipeline (MADD -> decoupling path ->
/// parallel meshing -> sink). Its options, statistics and planning rules are in
/// pipeline/options.hpp, pipeline/statistics.hpp and pipeline/planning.hpp; pdd::generate
/// (generate.hpp) is the one-call path.
#pragma once

#include <pdd/concepts/delaunay_mesher.hpp>
#include <pdd/concepts/executor.hpp>
#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/decoupling/decoupled_decomposition.hpp>
#include <pdd/decoupling/decoupling_parameter.hpp>
#include <pdd/errors.hpp>
#include <pdd/geometry/properties.hpp>
#include <pdd/kernels/cgal/mesher.hpp>
#include <pdd/madd/decompose.hpp>
#include <pdd/madd/decomposition.hpp>
#include <pdd/madd/decomposition_statistics.hpp>
#include <pdd/madd/gradation_control.hpp>
#include <pdd/madd/madd_options.hpp>
#include <pdd/madd/madd_start.hpp>
#include <pdd/meshing/mesh_subdomains.hpp>
#include <pdd/parallel/tbb_executor.hpp>
#include <pdd/partition/default_partitioner.hpp>
#include <pdd/pipeline/detail/domain_reading.hpp>
#include <pdd/pipeline/detail/graded_path.hpp>
#include <pdd/pipeline/detail/memory_check.hpp>
#include <pdd/pipeline/detail/path_plan.hpp>
#include <pdd/pipeline/detail/plan.hpp>
#include <pdd/pipeline/detail/record.hpp>
#include <pdd/pipeline/detail/uniform_path.hpp>
#include <pdd/pipeline/detail/whole_domain.hpp>
#include <pdd/pipeline/options.hpp>
#include <pdd/pipeline/planning.hpp>
#include <pdd/pipeline/statistics.hpp>
#include <pdd/pipeline/system.hpp>
#include <pdd/shielding/shield_decomposition.hpp>
#include <pdd/sizing/any_sizing.hpp>
#include <pdd/sizing/sizing_range.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace pdd {

/// The decoupling pipeline in stages (dissertation 6.4, Algorithm 6.1; 7.4-7.5):
/// decompose() runs MADD into N subdomains, decouple() computes k_i per subdomain and the
/// graded decoupling path (Theorem 22, Lemma 9; one k where k is set), mesh(sink) meshes every
/// subdomain independently on the executor and streams the meshes to a MeshSink. Each stage
/// runs the earlier ones if needed; its results can be inspected (and changed) before the next.
/// With N = 1 there is no decomposition: mesh() runs the kernel on the whole domain and
/// delivers it as subdomain 0.
/// \tparam M a DelaunayMesher. \tparam P a GraphPartitioner. \tparam E an Executor (built from
/// options.threads when it takes a thread count).
/// Thread-safety: one pipeline object is used from one thread (its stages run in parallel
/// inside).
template <DelaunayMesher M = cgal::mesher, GraphPartitioner P = default_partitioner,
          Executor E = tbb_executor>
class pipeline {
public:
  /// Checks the options (check_generate_options), validates the domain once
  /// (detail::read_domain; one not of closed loops is read by Triangle's rule and decoupled
  /// from its faces, detail::plan_general_domain),
  /// estimates the mesh size (pdd::estimate_mesh_size: the area bound, the sizing field and
  /// the local feature size; size_estimate()) and plans N from it (automatic_subdomains when
  /// options.subdomains == 0 and some area bound is given; N = 1 without any). \throws
  /// pdd::decomposition_error for contradicting options; pdd::geometry_error for an invalid
  /// domain.
  pipeline(pslg domain, generate_options options, M mesher = {}, P partitioner = {})
      : domain_(std::move(domain)), options_(std::move(options)), mesher_(std::move(mesher)),
        partitioner_(std::move(partitioner)),
        executor_(detail::make_executor<E>(options_.threads)) {
    check_generate_options(options_);
    if (options_.sizing) sizing_min_ = sizing_range(options_.sizing, bounding_box(domain_)).lo;
    detail::domain_reading read =
        detail::read_domain(domain_, options_, decoupling_criteria().max_area);
    general_ = read.general;
    area_ = read.area;
    estimate_ = read.estimate;
    start_ = std::move(read.start);
    stats_.threads = executor_.concurrency();
    stats_.estimated_triangles = estimate_.triangles;
    stats_.general_domain = general_;
    const detail::general_domain_plan general_plan =
        general_ ? detail::plan_general_domain(start_ ? &*start_ : nullptr)
                 : detail::general_domain_plan{};
    stats_.subdomains =
        detail::planned_subdomains(options_, stats_.estimated_triangles, stats_.threads,
                                   general_ ? &general_plan : nullptr, stats_.plan_reason);
    // the graded method (Algorithm 7.1 + graded path with Theorem 26's shields) where k is
    // neither scaled nor overridden
    graded_plan_ = options_.sizing && stats_.subdomains > 1 &&
                   !(options_.decoupling.k_override > 0.0) && options_.decoupling.k_scale == 1.0;
    if (general_) return; // the geometric path measures lfs_min on closed loops
    geometric_plan_ = detail::choose_geometric_path(
        domain_, options_, std::min(options_.criteria.max_area, sizing_min_), stats_);
    geometric_reason_ = stats_.plan_reason;
  }

  /// True when the domain is not one of closed loops (pdd::has_closed_loops): Triangle's rule,
  /// decoupled from its faces or meshed whole (statistics().plan_reason says which).
  bool general_domain() const noexcept { return general_; }

  /// N, the number of subdomains this pipeline uses.
  std::size_t subdomains() const noexcept { return stats_.subdomains; }
  /// The domain area (pdd::domain_area).
  double domain_area_value() const noexcept { return area_; }
  const generate_options& options() const noexcept { return options_; }
  const pslg& domain() const noexcept { return domain_; }

  /// \throws pdd::limit_error when meshing into a sink of type S would exceed
  /// options.max_triangles, or (max_triangles 0, check_memory) physical memory (kept in memory
  /// or not, see sink_retains_meshes and estimate_peak_bytes), or 32-bit indices in a kept
  /// mesh; the message gives the estimate, the feature that causes it and the memory needed.
  template <MeshSink S>
  void check_memory() const {
    detail::check_size_plan({.triangles = planned_triangles(),
                             .estimate = &estimate_,
                             .domain = &domain_,
                             .subdomains = stats_.subdomains,
                             .threads = stats_.threads,
                             .retains_meshes = sink_retains_meshes<S>,
                             .max_triangles = options_.max_triangles,
                             .check_memory = options_.check_memory});
  }

  /// The size estimate the plan uses (pdd::estimate_mesh_size) and its cause.
  const mesh_size_estimate& size_estimate() const noexcept { return estimate_; }

  /// Stage 1: MADD into N subdomains (nothing when N == 1; the decomposition is then empty).
  /// \throws pdd::decomposition_error when the domain cannot be split as asked.
  const decomposition& decompose() {
    if (decomposed_) return decomposition_;
    const auto t0 = std::chrono::steady_clock::now();
    if (stats_.subdomains > 1) {
      madd_options mo = options_.madd;
      mo.subdomains = stats_.subdomains;
      mo.max_subdomain_area = std::numeric_limits<double>::infinity();
      mo.threads = options_.threads;
      madd_used_ = mo;
      graded_madd_ = graded_plan_;
      try {
        run_madd(mo);
      } catch (const decomposition_error& e) {
        // automatic N on a general domain whose faces MADD cannot split (separators kept
        // away from its dangling segments and isolated vertices): one subdomain
        if (!general_ || options_.subdomains != 0) throw;
        fall_back_to_whole_domain(std::string("one subdomain: MADD cannot split the faces of "
                                              "this domain (") +
                                  e.what() + ")");
      }
    }
    if (!geometric_plan_) start_.reset(); // MADD's regions (the geometric path: decouple())
    stats_.timings.decompose = seconds_since(t0);
    decomposed_ = true;
    return decomposition_;
  }

  /// Stage 2: the decoupling path (runs decompose() first if needed). Empty when N == 1,
  /// including after an automatic plan's fallback (statistics().monolithic_fallback).
  /// \throws as pdd::decouple.
  const decoupled_decomposition& decouple() {
    if (decoupled_) return decoupled_decomposition_;
    decompose();
    const auto t0 = std::chrono::steady_clock::now();
    const double decompose_before = stats_.timings.decompose; // a second MADD run adds to it
    if (stats_.subdomains > 1) {
      build_path();
      // automatic N on the geometric path: a smaller cap once before falling back
      if (too_many_split_points() && decompose_geometric_again() && stats_.subdomains > 1)
        build_path();
      if (too_many_split_points())
        fall_back_to_whole_domain( // the geometric plan's reason stays, with its rounds
            (geometric_plan_ ? stats_.plan_reason + "; " : std::string()) +
            detail::split_point_reason(stats_.split_points, stats_.estimated_triangles,
                                       options_.planning));
    }
    start_.reset(); // MADD's regions are not needed again
    stats_.path = detail::path_name(stats_, geometric_plan_);
    stats_.timings.decouple = seconds_since(t0) - (stats_.timings.decompose - decompose_before);
    decoupled_ = true;
    return decoupled_decomposition_;
  }

  /// Stage 3: meshes every subdomain (runs decouple() first if needed) and delivers the
  /// meshes to `sink` (see pdd::mesh_subdomains; N == 1: the whole domain as subdomain 0).
  /// \throws pdd::limit_error (check_memory<S>), pdd::meshing_error with the subdomain id,
  /// pdd::decoupling_error when invariance repairs run out.
  template <MeshSink S>
  const generate_statistics& mesh(S& sink) {
    decouple();
    check_memory<S>();
    const auto t0 = std::chrono::steady_clock::now();
    detail::timed_sink<S> timed{sink};
    if (stats_.subdomains <= 1) {
      timed.start(1);
      triangle_mesh m = mesh_whole(stats_.shielded_triangles);
      stats_.triangles = m.triangles.size();
      timed.consume(0, std::move(m));
      timed.finish();
    } else {
      detail::record_meshing(mesh_subdomains(decoupled_decomposition_,
                                             {options_.criteria, options_.decoupling.max_repairs,
                                              options_.sizing, gradation_.expected_triangles},
                                             mesher_, executor_, timed),
                             decoupled_decomposition_, stats_);
    }
    stats_.timings.merge = timed.finish_seconds;
    stats_.timings.mesh = seconds_since(t0) - timed.finish_seconds;
    const generate_timings& t = stats_.timings;
    stats_.timings.total = t.decompose + t.decouple + t.mesh + t.merge;
    return stats_;
  }

  /// The triangles the size check plans for: the estimate (pdd::estimate_mesh_size), plus, once
  /// the decoupling path exists, 4 per split point (the kernel grades out from the separators).
  double planned_triangles() const noexcept {
    return stats_.estimated_triangles + 4.0 * static_cast<double>(stats_.split_points);
  }

  /// The kernel on the whole domain (the N == 1 path), markers 0. Input angles < 60 deg are
  /// shielded first (pdd::shield, Algorithm 8.2 with N = 1): the kernel meshes D' and the
  /// shielded triangles are added as they are.
  /// \throws pdd::meshing_error(-1, ...) from the kernel, or when it split a shield edge;
  /// pdd::geometry_error as pdd::shield.
  triangle_mesh mesh_whole() const {
    std::size_t shielded = 0;
    return mesh_whole(shielded);
  }
  /// As mesh_whole(); `shielded_triangles` receives the number of shielded triangles.
  triangle_mesh mesh_whole(std::size_t& shielded_triangles) const {
    return detail::mesh_whole_domain(mesher_, domain_, general_, options_.criteria, options_.sizing,
                                     decoupling_criteria().max_area, shielded_triangles);
  }

  /// The statistics so far.
  const generate_statistics& statistics() const noexcept { return stats_; }
  generate_statistics& statistics() noexcept { return stats_; }
  /// The decoupled decomposition (after decouple(); may be changed before mesh()).
  decoupled_decomposition& decoupled() noexcept { return decoupled_decomposition_; }
  const E& executor() const noexcept { return executor_; }

private:
  /// The decoupling path on decomposition_ with its shields (Algorithm 8.2; k from the shielded
  /// D_i'), recorded: one k_i per subdomain (Theorem 22) for a field and for the uniform bound
  /// alike, so a short separator or a small feature lowers k only beside it; one k (Theorem 15)
  /// only where k is set.
  void build_path() {
    std::vector<subdomain_shields> shields;
    if (!try_graded_path(shields))
      decoupled_decomposition_ = detail::build_uniform_path(
          decomposition_, options_.decoupling, decoupling_criteria(), executor_, shields);
    decoupled_decomposition_.shields.resize(shields.size());
    for (std::size_t s = 0; s < shields.size(); ++s)
      decoupled_decomposition_.shields[s] = std::move(shields[s].triangles);
    detail::record_path(decoupled_decomposition_, stats_);
  }

  /// Automatic N with too many split points (detail::too_many_split_points: one subdomain).
  bool too_many_split_points() const {
    return options_.subdomains == 0 && detail::too_many_split_points(stats_, options_.planning);
  }

  /// The geometric path with too many split points: MADD and the loop once more with half the
  /// loop's cap (the cap trades the grading towards tiny features against separator length; on
  /// the Bahamas at 2M triangles 4096 left 108K split points, 5.4 % of the estimate, 2048 left
  /// 95K). False (nothing changed) off that path, after the second try, or where half the cap
  /// is below 4N or would not bind.
  bool decompose_geometric_again() {
    const std::size_t cap = stats_.geometric_cap / 2;
    if (!geometric_plan_ || !start_ || geometric_retried_ || cap < 4 * madd_used_.subdomains ||
        stats_.subdomains <= cap)
      return false;
    const auto t0 = std::chrono::steady_clock::now();
    geometric_retried_ = true;
    stats_.plan_reason =
        geometric_reason_ + "; " + detail::geometric_retry_reason(stats_, options_.planning, cap);
    if (options_.geometric_field == geometric_mesh_field::algorithm_8_3)
      options_.sizing = user_sizing_;
    options_.geometric_loop.max_subdomains = cap;
    stats_.estimated_triangles = estimate_.triangles; // F's rounds scale it (record_geometric)
    graded_plan_ = graded_madd_;
    gradation_ = {};
    decoupled_decomposition_ = {};
    madd_with(madd_used_);
    stats_.timings.decompose += seconds_since(t0);
    return true;
  }

  /// Stage 1 of the graded method: Algorithm 7.1 (see generate_options::gradation) into
  /// decomposition_, with its measurements in gradation_ and the statistics.
  void decompose_graded(const madd_options& mo) {
    const gradation_options go = detail::graded_stage_options(options_, stats_.subdomains);
    decomposition_ = gradation_controlled_decompose(*start_, options_.sizing, go, mo, partitioner_,
                                                    &gradation_, &stats_.decomposition);
    detail::record_gradation(gradation_, stats_);
  }

  /// The geometric path (detail::run_geometric): its decomposition replaces MADD's, and with
  /// geometric_mesh_field::algorithm_8_3 its F replaces f.
  void adopt_geometric(const madd_options& mo) {
    geometric_decomposition gd =
        detail::run_geometric(domain_, std::move(decomposition_), options_, stats_.subdomains, mo,
                              partitioner_, executor_, &*start_);
    decomposition_ = std::move(gd.parts);
    stats_.subdomains = decomposition_.subdomains.size();
    user_sizing_ = options_.sizing;
    if (options_.geometric_field == geometric_mesh_field::algorithm_8_3)
      options_.sizing = *gd.sizing.field;
    graded_plan_ = true;
    if (detail::record_geometric(gd, options_, stats_, gradation_)) fall_back_to_whole_domain("");
  }

  /// Builds the graded path with shields (detail::build_graded_path: Theorem 26's l_i per
  /// subdomain, then Theorem 22's path) into decoupled_decomposition_ and `shields`; false
  /// (with the reason in the statistics, nothing changed) when k is overridden or scaled.
  bool try_graded_path(std::vector<subdomain_shields>& shields) {
    if (options_.decoupling.k_override > 0.0 || options_.decoupling.k_scale != 1.0) {
      stats_.graded_fallback = "decoupling.k_override or decoupling.k_scale set";
      return false;
    }
    decoupled_decomposition_ = detail::graded_pipeline_path(decomposition_, options_, gradation_,
                                                            executor_, stats_, shields);
    return true;
  }

  /// MADD (graded or not, geometric adoption) with mo; on a general domain the separators keep
  /// 4 k_area from its dangling segments and isolated vertices (madd_options::feature_clearance),
  /// or, when N cannot be reached so, the splits' boundary spacing h.
  void run_madd(madd_options mo) {
    if (general_ && mo.feature_clearance == 0.0) {
      const double term = decoupling_area_term(decoupling_criteria());
      if (std::isfinite(term)) {
        mo.feature_clearance = 4.0 * term;
        try {
          madd_with(mo);
          return;
        } catch (const decomposition_error&) {
          mo.feature_clearance = 0.0;
          stats_.decomposition = {};
        }
      }
    }
    madd_with(mo);
  }

  /// One MADD run with mo: graded (Algorithm 7.1) or not, then the geometric path's adoption.
  void madd_with(const madd_options& mo) {
    PDD_ASSERT(start_); // read with the plan: N > 1 needs options.subdomains != 1
    if (graded_plan_)
      decompose_graded(mo);
    else
      decomposition_ = pdd::decompose(*start_, mo, partitioner_, &stats_.decomposition);
    stats_.subdomains = decomposition_.subdomains.size();
    if (geometric_plan_) adopt_geometric(mo);
  }

  /// The criteria the decoupling path and the shields are built for: max_area lowered to the
  /// sizing field's minimum over the domain (the interim rule, see generate_options::sizing).
  mesh_criteria decoupling_criteria() const {
    mesh_criteria c = options_.criteria;
    c.max_area = std::min(c.max_area, sizing_min_);
    return c;
  }

  /// N = 1 after all (`why`, if not empty, becomes the plan's reason); the user's field again.
  void fall_back_to_whole_domain(const std::string& why) {
    if (!why.empty()) stats_.plan_reason = why;
    if (geometric_plan_) options_.sizing = user_sizing_;
    geometric_plan_ = false;
    detail::reset_decoupling_statistics(stats_);
    gradation_ = {};
    decomposition_ = {};
    decoupled_decomposition_ = {};
  }

  pslg domain_;
  generate_options options_;
  M mesher_;
  P partitioner_;
  E executor_;
  double area_ = 0.0;
  mesh_size_estimate estimate_;
  /// Lower bound of the sizing field over the domain (infinity without a field).
  double sizing_min_ = std::numeric_limits<double>::infinity();
  bool decomposed_ = false, decoupled_ = false;
  /// The graded method's decomposition (Algorithm 7.1) is used (see the constructor).
  bool graded_plan_ = false;
  /// The geometric path is planned / used (options_.sizing: its F, user_sizing_: the user's).
  bool geometric_plan_ = false;
  /// The geometric path: the plan's reason, MADD's options and graded plan before the loop, and
  /// whether it ran a second time (decompose_geometric_again).
  std::string geometric_reason_;
  madd_options madd_used_;
  bool graded_madd_ = false, geometric_retried_ = false;
  /// The domain is not one of closed loops (see general_domain()).
  bool general_ = false;
  std::optional<madd_start> start_; ///< until decompose(): the regions MADD starts from
  any_sizing user_sizing_;
  gradation_report gradation_;
  decomposition decomposition_;
  decoupled_decomposition decoupled_decomposition_;
  generate_statistics stats_;
};

} // namespace pdd
