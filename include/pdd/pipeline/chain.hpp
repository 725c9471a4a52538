/// \file chain.hpp
/// The chain a pdd::run_plan runs: decomposition -> decoupled decomposition -> meshes into a
/// sink, each stage a value (pdd::run_state) handed to the next. A stage that finds the plan
/// cannot go on as planned returns the plan it goes on with (pipeline/run_plan.hpp: the whole
/// domain, or the geometric loop once more); nothing rewrites the caller's options.
#pragma once

#include <pdd/concepts/delaunay_mesher.hpp>
#include <pdd/concepts/executor.hpp>
#include <pdd/concepts/graph_partitioner.hpp>
#include <pdd/concepts/mesh_sink.hpp>
#include <pdd/core/decomposition.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/decoupling/decoupled_decomposition.hpp>
#include <pdd/decoupling/decoupling_parameter.hpp>
#include <pdd/errors.hpp>
#include <pdd/madd/decompose.hpp>
#include <pdd/madd/gradation_control.hpp>
#include <pdd/madd/madd_options.hpp>
#include <pdd/meshing/mesh_subdomains.hpp>
#include <pdd/pipeline/detail/face_path.hpp>
#include <pdd/pipeline/detail/graded_path.hpp>
#include <pdd/pipeline/detail/path_plan.hpp>
#include <pdd/pipeline/detail/plan.hpp>
#include <pdd/pipeline/detail/record.hpp>
#include <pdd/pipeline/detail/uniform_path.hpp>
#include <pdd/pipeline/detail/whole_domain.hpp>
#include <pdd/pipeline/options.hpp>
#include <pdd/pipeline/run_plan.hpp>
#include <pdd/pipeline/statistics.hpp>
#include <pdd/pipeline/system.hpp>
#include <pdd/shielding/shield_decomposition.hpp>
#include <pdd/sizing/any_sizing.hpp>

#include <chrono>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace pdd {

/// The chain's value between stages: the plan in force (a fallback's or a retry's once a stage
/// returned one), the decomposition, Algorithm 7.1's (or the geometric loop's) measurements, the
/// field the path and the kernel use, and the decoupling path (after stage 2).
struct run_state {
  /// The plan in force: plan_run's, or the fallback's or retry's a stage returned.
  run_plan plan;
  /// The decomposition into subdomains (after stage 1; one subdomain on the monolithic path).
  decomposition parts;
  /// Algorithm 7.1's (or the geometric loop's) measurements on `parts`; default where neither
  /// ran.
  gradation_report gradation;
  /// The user's field, or on the geometric path with geometric_mesh_field::algorithm_8_3 its F.
  any_sizing mesh_field;
  /// The decoupling path over `parts` (after stage 2).
  decoupled_decomposition path;
};

/// The statistics a plan starts with: N, the threads, the estimate, the reason.
inline generate_statistics planned_statistics(const run_plan& p, unsigned threads) {
  generate_statistics st;
  st.subdomains = p.subdomains;
  st.threads = threads;
  st.estimated_triangles = p.estimate.triangles;
  st.general_domain = p.general_domain;
  st.plan_reason = p.reason;
  if (p.subdomains <= 1) st.path = path_name(mesh_path::monolithic);
  return st;
}

/// The kernel's options for the subdomains of `s` (the field of the path, Algorithm 7.2's
/// expected triangles for the order of work).
inline meshing_options meshing_options_for(const run_state& s, const generate_options& o) {
  return {o.criteria, o.decoupling.max_repairs, s.mesh_field, s.gradation.expected_triangles,
          o.kept_subdomains};
}

namespace detail {

/// `s` goes on with plan `p` on the whole domain (its decomposition and path dropped, the
/// user's field again, the statistics of decoupling forgotten; `why`, when not empty, becomes
/// the reason).
inline void adopt_whole_domain(run_state& s, run_plan p, const generate_options& o,
                               generate_statistics& st) {
  s.plan = std::move(p);
  s.parts = {};
  s.gradation = {};
  s.path = {};
  s.mesh_field = o.sizing;
  reset_decoupling_statistics(st);
  st.plan_reason = s.plan.reason;
}

/// MADD's options for plan p: N subdomains, no area cap, o.threads.
inline madd_options madd_options_for(const run_plan& p, const generate_options& o) {
  madd_options mo = o.madd;
  mo.subdomains = p.subdomains;
  mo.max_subdomain_area = std::numeric_limits<double>::infinity();
  mo.threads = o.threads;
  return mo;
}

/// The geometric path (detail::run_geometric) on s.parts: its decomposition replaces MADD's,
/// with geometric_mesh_field::algorithm_8_3 its F becomes the mesh field; the whole domain when
/// Algorithm 8.3's over-refinement says decoupling would not pay (detail::record_geometric).
template <GraphPartitioner P, Executor E>
void adopt_geometric(run_state& s, const planned_run& in, const generate_options& o,
                     const madd_options& mo, const P& partitioner, const E& executor,
                     generate_statistics& st) {
  geometric_decomposition gd =
      run_geometric(in.domain, std::move(s.parts), o, st.subdomains, s.plan.geometric_cap, mo,
                    partitioner, executor, &*in.regions);
  s.parts = std::move(gd.parts);
  st.subdomains = s.parts.subdomains.size();
  if (o.geometric_field == geometric_mesh_field::algorithm_8_3) s.mesh_field = *gd.sizing.field;
  if (record_geometric(gd, o, st, s.gradation)) {
    const std::string reason = st.plan_reason; // record_geometric's, with its rounds
    adopt_whole_domain(s, whole_domain_plan(s.plan, reason), o, st);
  }
}

/// The geometric path on a general PSLG (detail::face_geometric_decompose) on s.parts: the round
/// estimated to add the fewest triangles replaces MADD's decomposition; the rounds go to the
/// reason. Under automatic N, the whole domain when that round is estimated to add more than
/// planning.max_face_over_refinement of the estimated triangles (the estimate times
/// planning.face_over_refinement_margin).
template <GraphPartitioner P, Executor E>
void adopt_face_geometric(run_state& s, const planned_run& in, const generate_options& o,
                          const madd_options& mo, const P& partitioner, const E& executor,
                          generate_statistics& st) {
  face_path_result r =
      face_geometric_decompose(std::move(s.parts), o, st.subdomains, s.plan.geometric_cap, mo,
                               partitioner, executor, *in.regions);
  s.parts = std::move(r.parts);
  if (r.chosen != 0) s.gradation = {}; // k_i from the user's field over the new subdomains
  st.geometric_cap = geometric_cap(s.plan.geometric_cap, st.subdomains);
  st.subdomains = s.parts.subdomains.size();
  st.sizing_rounds = r.rounds.size();
  st.sizing_round_used = r.chosen;
  st.estimated_over_refinement.clear();
  st.plan_reason += face_path_reason(r, o);
  const std::optional<face_path_cost>& cost = r.rounds[r.chosen].cost;
  const double bound = o.planning.max_face_over_refinement * st.estimated_triangles;
  const double margin = o.planning.face_over_refinement_margin;
  if (o.subdomains != 0 || !cost || !(margin * cost->extra_triangles > bound)) return;
  st.plan_reason += "; " + number_text(margin) + " x " +
                    number_text(std::round(cost->extra_triangles)) + " > " +
                    number_text(100.0 * o.planning.max_face_over_refinement) +
                    " % of the estimated triangles (planning.max_face_over_refinement, " +
                    "face_over_refinement_margin): decoupling would not pay, one subdomain";
  adopt_whole_domain(s, whole_domain_plan(s.plan, st.plan_reason), o, st);
}

/// One MADD run with mo into s: Algorithm 7.1 where the plan says so (with the user's field),
/// else N-way MADD; then the geometric path's adoption.
template <GraphPartitioner P, Executor E>
void madd_with(run_state& s, const planned_run& in, const generate_options& o,
               const madd_options& mo, const P& partitioner, const E& executor,
               generate_statistics& st) {
  PDD_ASSERT(in.regions); // read with the plan: N > 1 needs options.subdomains != 1
  if (s.plan.gradation_controlled) {
    const gradation_options go = graded_stage_options(o, s.plan.subdomains);
    s.parts = gradation_controlled_decompose(*in.regions, o.sizing, go, mo, partitioner,
                                             &s.gradation, &st.decomposition);
    record_gradation(s.gradation, st);
  } else {
    s.parts = pdd::decompose(*in.regions, mo, partitioner, &st.decomposition);
  }
  st.subdomains = s.parts.subdomains.size();
  if (s.plan.path != mesh_path::geometric) return;
  if (s.plan.general_domain)
    adopt_face_geometric(s, in, o, mo, partitioner, executor, st);
  else
    adopt_geometric(s, in, o, mo, partitioner, executor, st);
}

/// MADD for the plan of s; on a general domain the separators first keep 4 k_area from its
/// dangling segments and isolated vertices (madd_options::feature_clearance), and where N
/// cannot be reached so, the splits' boundary spacing h.
template <GraphPartitioner P, Executor E>
void run_madd(run_state& s, const planned_run& in, const generate_options& o, madd_options mo,
              const P& partitioner, const E& executor, generate_statistics& st) {
  if (s.plan.general_domain && mo.feature_clearance == 0.0) {
    const double term = decoupling_area_term(s.plan.decoupling_criteria);
    if (std::isfinite(term)) {
      mo.feature_clearance = 4.0 * term;
      try {
        madd_with(s, in, o, mo, partitioner, executor, st);
        return;
      } catch (const decomposition_error&) {
        mo.feature_clearance = 0.0;
        st.decomposition = {};
      }
    }
  }
  madd_with(s, in, o, mo, partitioner, executor, st);
}

/// The decoupling path of s.parts with its shields (Algorithm 8.2; k from the shielded D_i'),
/// recorded: one k_i per subdomain (Theorem 22) for a field and for the uniform bound alike,
/// so a short separator or a small feature lowers k only beside it; one k (Theorem 15) on the
/// uniform path, where k is set.
template <Executor E>
void build_path(run_state& s, const generate_options& o, const E& executor,
                generate_statistics& st) {
  std::vector<subdomain_shields> shields;
  if (s.plan.path == mesh_path::uniform) {
    st.graded_fallback = "decoupling.k_override or decoupling.k_scale set";
    s.path =
        build_uniform_path(s.parts, o.decoupling, s.plan.decoupling_criteria, executor, shields);
  } else {
    s.path =
        graded_pipeline_path(s.parts, o.criteria, s.mesh_field, s.gradation, executor, st, shields);
  }
  s.path.shields.resize(shields.size());
  for (std::size_t i = 0; i < shields.size(); ++i)
    s.path.shields[i] = std::move(shields[i].triangles);
  record_path(s.path, st);
}

} // namespace detail

/// Stage 1: the decomposition plan p asks for (nothing for N = 1): MADD, Algorithm 7.1 or the
/// geometric loop, from the regions `in` was read with. A general domain that MADD cannot split
/// under automatic N goes on with the whole domain.
/// \throws pdd::decomposition_error when the domain cannot be split as asked.
template <GraphPartitioner P, Executor E>
run_state decompose_stage(const run_plan& p, const planned_run& in, const generate_options& o,
                          const P& partitioner, const E& executor, generate_statistics& st) {
  run_state s{p, {}, {}, o.sizing, {}};
  st.estimated_triangles = p.estimate.triangles; // the geometric loop's F scales it
  if (p.subdomains <= 1) return s;
  try {
    detail::run_madd(s, in, o, detail::madd_options_for(p, o), partitioner, executor, st);
  } catch (const decomposition_error& e) {
    // automatic N on a general domain whose faces MADD cannot split (separators kept away
    // from its dangling segments and isolated vertices): one subdomain
    if (!p.general_domain || !p.automatic) throw;
    detail::adopt_whole_domain(
        s,
        whole_domain_plan(p, std::string("one subdomain: MADD cannot split the faces of this "
                                         "domain (") +
                                 e.what() + ")"),
        o, st);
  }
  return s;
}

/// Stage 2: the decoupling path of s (nothing for the whole domain). When it has too many split
/// points under automatic N, the plan's answer (pdd::plan_after_path) is taken: stage 1 again
/// with the geometric loop's smaller cap (its time added to st.timings.decompose), or the
/// whole domain.
/// \throws as pdd::decouple and pdd::decouple_graded.
template <GraphPartitioner P, Executor E>
run_state decouple_stage(run_state s, const planned_run& in, const generate_options& o,
                         const P& partitioner, const E& executor, generate_statistics& st) {
  while (s.plan.path != mesh_path::monolithic && st.subdomains > 1) {
    detail::build_path(s, o, executor, st);
    std::optional<run_plan> next =
        plan_after_path(s.plan, st.split_points, st.estimated_triangles, st.geometric_cap,
                        st.subdomains, st.plan_reason, o.planning);
    if (!next) break;
    if (next->path == mesh_path::monolithic) {
      detail::adopt_whole_domain(s, std::move(*next), o, st);
      break;
    }
    const auto t0 = std::chrono::steady_clock::now();
    st.plan_reason = next->reason;
    s = decompose_stage(*next, in, o, partitioner, executor, st);
    st.timings.decompose += seconds_since(t0);
  }
  st.path = path_name(st.subdomains <= 1 ? mesh_path::monolithic : s.plan.path);
  return s;
}

/// The kernel on the whole domain of `in` (the N = 1 path), markers 0, its small input angles
/// shielded first on a domain of closed loops (detail::mesh_whole_domain); `shielded_triangles`
/// receives their number.
/// \throws pdd::meshing_error(-1, ...) from the kernel, or when it split a shield edge;
/// pdd::geometry_error as pdd::shield.
template <DelaunayMesher M>
triangle_mesh mesh_whole_stage(const planned_run& in, const generate_options& o, const M& mesher,
                               std::size_t& shielded_triangles) {
  return detail::mesh_whole_domain(mesher, in.domain, in.plan.general_domain, o.criteria, o.sizing,
                                   in.plan.decoupling_criteria.max_area, shielded_triangles);
}

/// Stage 3: every subdomain of s meshed on the executor and delivered to `sink` as it is done
/// (pdd::mesh_subdomains), or the whole domain as subdomain 0; the time of the sink's finish()
/// goes to st.timings.merge.
/// \throws pdd::meshing_error with the subdomain id, pdd::decoupling_error when invariance
/// repairs run out.
template <DelaunayMesher M, Executor E, MeshSink S>
void mesh_stage(run_state& s, const planned_run& in, const generate_options& o, const M& mesher,
                const E& executor, S& sink, generate_statistics& st) {
  detail::timed_sink<S> timed{sink};
  if (st.subdomains <= 1) {
    timed.start(1);
    triangle_mesh m = mesh_whole_stage(in, o, mesher, st.shielded_triangles);
    st.triangles = m.triangles.size();
    timed.consume(0, std::move(m));
    timed.finish();
  } else {
    detail::record_meshing(
        mesh_subdomains(s.path, meshing_options_for(s, o), mesher, executor, timed), s.path, st);
  }
  st.timings.merge = timed.finish_seconds;
}

} // namespace pdd
