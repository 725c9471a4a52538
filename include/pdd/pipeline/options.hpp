/// \file options.hpp
/// pdd::generate_options: the options of pdd::generate and pdd::pipeline.
#pragma once

#include <pdd/core/index.hpp>
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/decoupling/geometric_decompose_options.hpp>
#include <pdd/errors.hpp>
#include <pdd/madd/gradation_options.hpp>
#include <pdd/madd/madd_options.hpp>
#include <pdd/sizing/any_sizing.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace pdd {

/// The automatic number of subdomains (pdd::automatic_subdomains) and the fallback to the
/// whole domain; used only when generate_options::subdomains is 0, except
/// min_face_path_triangles.
struct planning_options {
  /// The number of triangles aimed at per subdomain.
  double target_subdomain_triangles = 60000.0;
  /// At least this many subdomains per thread when running on several threads.
  unsigned min_subdomains_per_thread = 4;
  /// No subdomain is planned below this many triangles.
  double min_subdomain_triangles = 5000.0;
  /// Fall back to N = 1 when the decoupling path has more split points than this fraction of
  /// the estimated triangles. That happens when k is held down by a small input feature
  /// (k <= lfs_min): the uniform method then refines every separator to that scale and would
  /// over-refine the mesh (dissertation 6.3; the graded method of ch. 7 is the remedy).
  double max_split_point_fraction = 0.05;
  /// On the geometric path of a domain that is not one of closed loops: fall back to N = 1 when
  /// the graded path of the round taken is estimated to add more than this fraction of the
  /// estimated triangles (detail::path_edge_cost; issue 36 asks for at most 3 % over the
  /// whole-domain mesh). The estimate errs high on Triangle's la.poly (13,924 estimated, 6,095
  /// measured at --max-area 0.001) and is close on a pinching wedge (7,624 / 8,032).
  double max_face_over_refinement = 0.03;
  /// The face path's estimate of the triangles its split points add is multiplied by this
  /// before it is compared with max_face_over_refinement: the largest ratio of measured to
  /// estimated added triangles over the layered benchmarks (benchmarks/results/layered.md at
  /// 633b68c: lenses at --max-area 0.001, 22,290 measured against 16,778 estimated, 1.33; la.poly,
  /// a wedge and lenses elsewhere 0.55-1.0), so that automatic N does not take a plan the estimate
  /// puts just under the bound.
  double face_over_refinement_margin = 1.35;
  /// Geometric sizing auto plans the geometric path on a domain that is not one of closed loops
  /// (for automatic and requested N) only from this many estimated triangles (below the 50K
  /// from which issue 36 asks for 3 %, so that every mesh it covers gets the path): its rounds of
  /// Algorithm 7.1 cost more than they save on small meshes (a fuzz input at N = 2: 1.25 s against
  /// 0.13 s), where a small feature's split points are cheap in time. --geometric-sizing on plans
  /// it at every size.
  double min_face_path_triangles = 20000.0;
};

/// Whether the pipeline builds the sizing function from the geometry (dissertation 8.2,
/// Algorithm 8.3, iterated with the decomposition: pdd::geometric_decompose) and decouples
/// with it (generate_options::geometric_sizing).
enum class geometric_sizing_mode {
  /// With criteria.max_area alone (no field) and automatic N, when N > 1 and some feature is
  /// smaller than the mesh (lfs_min of the domain below the
  /// area term (1/2) sqrt(m / sqrt2) of Proposition 20, m the smallest area bound), so that
  /// k_i would be held down by it in every subdomain beside it (split points of the size of
  /// the feature along all their separators). On a domain that is not one of closed loops,
  /// for automatic and requested N, with or without a field, from
  /// planning.min_face_path_triangles (detail::choose_face_geometric_path).
  automatic,
  on,  ///< whenever N > 1 (and no k_scale / k_override)
  off, ///< never (N-way MADD or Algorithm 7.1, and the graded path, as before)
};

/// The area bound the kernel meshes the geometric path's subdomains with (and the graded
/// decoupling path's m(D_i) comes from).
enum class geometric_mesh_field {
  /// min(criteria.max_area, sizing), the user's f (default). The graded path's k_i <=
  /// lfs_min(D_i) (Theorem 15's term in Proposition 20, pdd::decouple_graded) already keeps
  /// every piece of a subdomain holding a tiny feature safe from splitting, and the
  /// decomposition graded towards the features keeps those subdomains, and so their short
  /// pieces, small; the kernel grades towards the features by itself, as the monolithic one
  /// does. This departs from the text (8.2), which meshes with F: F is small over the whole
  /// subdomain that holds a feature (measured: 2.4M triangles with f against 67M with F on
  /// the Bahamas at 2M, on the same 4096 subdomains).
  user,
  /// Algorithm 8.3's F (the text): F <= f, m_F(D_i) <= 4 sqrt2 e_i^2.
  algorithm_8_3,
};

/// The decoupling path's own knobs (the criteria and the sizing are generate_options'): k of
/// Theorem 15 and the invariance repairs of the meshing stage.
struct decoupling_path_options {
  /// Multiplies the decoupling parameter k of Theorem 15 (in (0, 1] keeps the guarantee).
  double k_scale = 1.0;
  /// > 0: use this k instead (experiments, and pdd::triangle::triangulate's strips of a vertex
  /// set, whose separators hold no vertex in their pieces' disks; see
  /// decoupling_options::k_override).
  double k_override = 0.0;
  /// Invariance repair rounds (see mesh_subdomains; the theory says none are ever needed).
  unsigned max_repairs = 3;
};

/// Options of pdd::generate and pdd::pipeline.
struct generate_options {
  /// Quality and uniform size bounds of every triangle.
  mesh_criteria criteria;
  /// A sizing field besides criteria.max_area: the area bound at p is
  /// min(criteria.max_area, sizing.area_at(p)). Empty (default): criteria.max_area alone.
  /// With N > 1 the graded method of dissertation ch. 7: the gradation-controlled
  /// decomposition (pdd::gradation_controlled_decompose, Algorithm 7.1 with `gradation`) and
  /// the graded decoupling path (pdd::decouple_graded: k_i per subdomain from m(D_i), lowered
  /// where relation 7.1 needs it, Theorem 22); the subdomains are meshed largest expected
  /// work first (Algorithm 7.2). Input angles below 60 degrees are shielded per subdomain with
  /// Theorem 26's l_i from m(D_i) (pdd::shield_graded_decomposition). Where k_scale or
  /// k_override are set, N-way MADD and the interim uniform path are used instead: k from
  /// the field's minimum over the domain's bounding box (generate_statistics::graded_fallback
  /// says why). The kernel meshes each subdomain with the field itself either way.
  /// Without a field (criteria.max_area alone) the decoupling path is the graded one too, on
  /// N-way MADD's subdomains: m(D_i) = max_area, k_i = min(lfs_min(D_i), sqrt 3 L_i / 4, the area
  /// term) per subdomain, lowered where relation 7.1 needs it, so a short separator or a small
  /// feature holds k down only beside it (one global k where k_scale or k_override are set).
  any_sizing sizing{};
  /// Algorithm 7.1's options for the graded method (R1, R2, the termination minimum and the
  /// most subdomains). The pipeline sets the rest: automatic N (subdomains == 0): T =
  /// target_subdomain_triangles (Condition 3) and at least the automatic plan's N subdomains;
  /// a requested N: at least N subdomains (largest expected work first) and no Condition 3;
  /// max_area = criteria.max_area. Leave max_subdomain_triangles, min_subdomains and max_area
  /// at their defaults (check_generate_options).
  gradation_options gradation{};
  /// N, the number of subdomains. 0: automatic (pdd::automatic_subdomains, which grows with
  /// `threads`: the mesh is bitwise the same for every thread count only for a given N); 1:
  /// the kernel meshes the whole domain at once (no decomposition).
  std::size_t subdomains = 0;
  /// Threads of every stage; 0: all cores.
  unsigned threads = 0;
  /// MADD options. Its `subdomains` and `threads` are the two fields above: leave them at
  /// their defaults or give the same values (check_generate_options); `max_subdomain_area`
  /// must stay infinite (the pipeline plans N itself); `min_separator_angle_deg` (Phi0) must
  /// be >= 60.
  madd_options madd;
  /// k of the decoupling path and the invariance repairs.
  decoupling_path_options decoupling;
  /// Refuse (pdd::limit_error) an area bound whose mesh would not fit in physical memory
  /// (when max_triangles is 0).
  bool check_memory = true;
  /// Refuse (pdd::limit_error), before any work, a run whose estimated triangle count
  /// (pdd::estimate_mesh_size: the area bound and the local feature size) exceeds this. 0:
  /// the limit is what fits in physical memory with the sink (check_memory).
  std::size_t max_triangles = 0;
  /// Automatic N (subdomains == 0); a requested N is always used.
  planning_options planning;
  /// The geometric path (Algorithm 8.3 and the loop of pdd::geometric_decompose): the field
  /// F <= min(criteria.max_area, sizing) it builds chooses the decomposition graded towards
  /// the tiny features; the graded decoupling path and the kernel then use geometric_field
  /// (small input angles: the graded path's shields, Theorem 26, from m(D_i));
  /// generate_statistics::path and plan_reason say what was used and why.
  geometric_sizing_mode geometric_sizing = geometric_sizing_mode::automatic;
  /// What the geometric path meshes with: the user's field (default) or Algorithm 8.3's F.
  geometric_mesh_field geometric_field = geometric_mesh_field::user;
  /// With the geometric path on Algorithm 8.3's F and automatic N: fall back to N = 1 when its
  /// estimated over-refinement (the integral of 1 / F over that of 1 / f, minus 1) exceeds
  /// this. (With the user's field the split points decide, planning.max_split_point_fraction.)
  double max_geometric_over_refinement = 0.25;
  /// Bounds of the geometric path's loop (target over-refinement, rounds, subdomains; the
  /// pipeline raises max_subdomains to at least 4 N).
  geometric_decompose_options geometric_loop{};
  /// Subdomains not meshed in mesh()'s first round: their meshes exist already (a resumed
  /// run's intact pieces, pdd::resumable_piece_sink; meshing_options::kept). Set it after the
  /// plan is known (pipeline::keep_subdomains); ignored when N == 1.
  std::vector<index_t> kept_subdomains{};
};

/// Rejects a generate_options whose embedded madd_options contradicts the pipeline's own
/// fields, instead of silently overriding it: madd.subdomains and madd.threads must be their
/// defaults or equal subdomains and threads (when subdomains is 0, automatic, madd.subdomains
/// must be its default), and madd.max_subdomain_area must be infinite. Also refuses, up front
/// and for every N, a separator angle bound madd.min_separator_angle_deg (Phi0) outside
/// [60, 90): the decoupling path (Lemma 9, Theorem 15) and the shields (Algorithm 8.2,
/// Theorem 24) assume that every subdomain meshes with a Ruppert-type kernel, i.e. that
/// separators meet the boundary and each other at >= 60 deg (criterion C1, ch. 3-4).
/// \throws pdd::decomposition_error naming the field. Complexity O(1).
inline void check_generate_options(const generate_options& o) {
  const madd_options defaults;
  const auto bad = [](const std::string& what) {
    throw decomposition_error("generate_options: " + what);
  };
  if (o.madd.subdomains != defaults.subdomains && o.madd.subdomains != o.subdomains)
    bad("madd.subdomains = " + std::to_string(o.madd.subdomains) + " contradicts subdomains = " +
        std::to_string(o.subdomains) + " (the pipeline uses subdomains; leave madd.subdomains)");
  if (o.madd.threads != defaults.threads && o.madd.threads != o.threads)
    bad("madd.threads = " + std::to_string(o.madd.threads) + " contradicts threads = " +
        std::to_string(o.threads) + " (the pipeline uses threads; leave madd.threads)");
  if (o.madd.max_subdomain_area != defaults.max_subdomain_area)
    bad("madd.max_subdomain_area is not used by the pipeline (it plans the number of "
        "subdomains itself; set subdomains instead)");
  const gradation_options gdefaults;
  if (o.gradation.max_subdomain_triangles != gdefaults.max_subdomain_triangles ||
      o.gradation.min_subdomains != gdefaults.min_subdomains ||
      o.gradation.max_area != gdefaults.max_area ||
      o.gradation.mean_area_fraction != gdefaults.mean_area_fraction)
    bad("gradation.max_subdomain_triangles, min_subdomains, max_area and mean_area_fraction are "
        "set by the pipeline (target_subdomain_triangles, subdomains, criteria.max_area); leave "
        "them at their defaults");
  check_gradation_options(o.gradation);
  const double phi0 = o.madd.min_separator_angle_deg;
  if (!(phi0 >= 60.0 && phi0 < 90.0))
    bad("madd.min_separator_angle_deg is " + std::to_string(phi0) +
        ", but must lie in [60, 90): the decoupling path (Theorem 15) and the shields of small "
        "angles (Algorithm 8.2) need separators that meet the boundary and each other at >= 60 "
        "deg (Phi0 of dissertation ch. 3-4), so that every subdomain meets the input-angle "
        "condition of the Ruppert-type kernel");
}

} // namespace pdd
