/// \file statistics.hpp
/// pdd::generate_statistics and pdd::generate_timings: what a pipeline run did.
#pragma once

#include <pdd/madd/decomposition_statistics.hpp>
#include <pdd/meshing/meshing_statistics.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace pdd {

/// Wall-clock seconds of the stages.
struct generate_timings {
  double decompose = 0.0; ///< MADD (0 when N == 1)
  double decouple = 0.0;  ///< k and the decoupling path
  double mesh = 0.0;      ///< kernel on every subdomain, checks, delivery to the sink
  double merge = 0.0;     ///< the sink's finish() (the in-memory merge)
  /// The whole run: generate() measures it from call to return; a pipeline's mesh() sets the
  /// sum of the four stages above.
  double total = 0.0;
};

/// What a pipeline run did.
struct generate_statistics {
  std::size_t subdomains = 0; ///< N used
  unsigned threads = 0;       ///< the executor's concurrency
  /// The plan's estimate (pdd::estimate_mesh_size: the integral of 1 / (0.656 F) with F also
  /// bounded by the local feature size).
  double estimated_triangles = 0.0;
  double k = 0.0;                   ///< decoupling parameter (0 when N == 1)
  double lfs_min = 0.0;             ///< min over subdomains (0 when N == 1)
  double shortest_separator = 0.0;  ///< L (0 when N == 1)
  std::size_t split_points = 0;     ///< vertices inserted on the separators
  std::size_t interface_splits = 0; ///< interface pieces the kernel split (should be 0)
  /// Input angles < 60 deg shielded (dissertation 8.1): shielded triangles in the mesh.
  std::size_t shielded_triangles = 0;
  std::size_t shield_splits = 0; ///< shield edges the kernel split (0; a split one throws)
  /// Subdomain meshings repeated by invariance repairs (meshing_statistics; 0 unless
  /// interface_splits > 0).
  std::size_t remeshed_subdomains = 0;
  /// Invariance repair rounds run (each halves k on the failing segments; at most
  /// meshing_options::max_repairs); 0 when no interface piece was split.
  std::size_t repair_rounds = 0;
  /// The automatic plan decomposed the domain but fell back to N = 1 because the decoupling
  /// path was too fine (see planning_options::max_split_point_fraction).
  bool monolithic_fallback = false;
  std::size_t triangles = 0; ///< triangles delivered
  std::size_t vertices = 0;  ///< vertices of the merged mesh (generate without a sink only)
  /// Wall-clock seconds of the stages.
  generate_timings timings;
  decomposition_statistics decomposition; ///< MADD's measurements (N > 1)
  /// What happened to each subdomain (its area, mesh size, kernel time, runs), by subdomain id.
  std::vector<subdomain_report> per_subdomain;
  /// N > 1: true when the graded decoupling path (decouple_graded, one k_i per subdomain;
  /// small input angles shielded per subdomain with Theorem 26's l_i) was used, with a field
  /// or the uniform bound; false when decoupling.k_scale or decoupling.k_override were in play
  /// and the uniform path with one k (from the field's minimum) was used instead
  /// (graded_fallback says why).
  bool graded_path = false;
  /// N > 1 and graded_path false: why the uniform path was taken instead (e.g.
  /// "decoupling.k_override or decoupling.k_scale set"); empty otherwise.
  std::string graded_fallback;
  std::vector<double> subdomain_k; ///< k_i per subdomain (graded path)
  double k_ratio_max = 0.0;        ///< max k_j / k_i across interfaces (graded path)
  /// With a sizing field and N > 1 when neither k_scale nor k_override is in play: the
  /// decomposition is Algorithm 7.1's (gradation_controlled_decompose) and these are measured
  /// on it: max M / m over subdomains (Condition 1), max m_i / m_j over separators
  /// (Condition 2), the subdomains / neighbour pairs left non-acceptable by the termination
  /// rule (gradation_options::min_subdomain_triangles), and whether max_subdomains stopped it.
  bool gradation_controlled = false;
  /// Max over subdomains of M(D_i) / m(D_i) (Condition 1 asks <= R1); 0 when not measured.
  double r1_max = 0.0;
  /// Max over separators of m_i / m_j (Condition 2 asks <= R2); 0 when not measured.
  double r2_max = 0.0;
  /// Subdomains with M > R1 m left by the termination rule (Condition 1 unmet).
  std::size_t condition_1_unmet = 0;
  /// Neighbour pairs with m_i > R2 m_j left by the termination rule (Condition 2 unmet).
  std::size_t condition_2_unmet = 0;
  /// Algorithm 7.1 stopped at gradation_options::max_subdomains with a subdomain still to split.
  bool gradation_capped = false;
  /// Subdomains whose k_i the graded path lowered so that relation 7.1 holds.
  std::size_t lowered_k = 0;
  /// The path taken: "monolithic" (N = 1), "uniform" (one k, Theorem 15), "graded" (k_i from
  /// the user's field, Theorem 22) or "geometric" (k_i from Algorithm 8.3's F, Theorem 22).
  std::string path;
  /// Why that path (the plan's rule and its numbers, or the fallback's).
  std::string plan_reason;
  /// The domain is not one of closed loops (pdd::has_closed_loops): Triangle's rule, meshed
  /// whole by the kernel (one subdomain; plan_reason says so).
  bool general_domain = false;
  /// The geometric path: rounds of decomposition + Algorithm 8.3 run (pdd::geometric_decompose),
  /// the estimated over-refinement of each (integral of 1 / F over that of 1 / f, minus 1) and
  /// the round used.
  std::size_t sizing_rounds = 0;
  /// One value per round, in round order (empty where the geometric path did not run, and on a
  /// general PSLG, whose rounds are judged by their split points: plan_reason lists them).
  std::vector<double> estimated_over_refinement;
  /// The index (0-based, in round order) of the round whose decomposition and F were used.
  std::size_t sizing_round_used = 0;
  /// The geometric loop's cap on subdomains in its last run (the option's, at least 4N, or half
  /// of it after a second try; kept after a fallback to one subdomain); 0 where it did not run.
  std::size_t geometric_cap = 0;
};

} // namespace pdd
