/// \file madd_options.hpp
/// pdd::madd_options: the options of the Medial Axis Domain Decomposition (dissertation
/// ch. 3-5).
#pragma once

#include <pdd/madd/decomposition_statistics.hpp>
#include <pdd/madd/split_policy.hpp>

#include <cstddef>
#include <limits>

namespace pdd {

/// How the boundary refinement length of a split is chosen (dissertation 4.1).
enum class madd_refinement_scale {
  /// Per subdomain: h = 4 A / (P r) for a subdomain of area A and perimeter P (h is a quarter
  /// of a square's side for r = 4, about half the width of a thin strip). Large subdomains,
  /// whose input segments are fine already, are not over-refined, and the leaves get the
  /// sqrt(N) scaling of 4.1 automatically (their size is sqrt(A/N)).
  subdomain,
  /// The dissertation's static MADD: h = L_a / (r sqrt N) for every split, L_a the average
  /// input segment length.
  global
};

/// Options of pdd::decompose (designated initialisers welcome).
struct madd_options {
  /// N: the number of subdomains (exactly), unless max_subdomain_area is finite or a
  /// split_policy is set (then the most subdomains made).
  std::size_t subdomains = 2;
  /// Phi0 (degrees, in (0, 90)): every angle a separator forms with the boundary or with
  /// another separator is >= Phi0 (criterion C1; 60 for Ruppert-type meshers).
  double min_separator_angle_deg = 60.0;
  /// 1: the first MADD algorithm (3.4, Algorithms 3.1-3.3: separators through circumcentres
  /// of junction triangles only; where a triangulation has no junction triangle at all, as
  /// an exactly symmetric subdomain whose Delaunay triangles are all right-angled, or no
  /// level gives a separator, the second algorithm splits that subdomain); 2: the second (3.5,
  /// Algorithms 3.4-3.6: Delaunay edges with good angles too).
  int algorithm = 2;
  /// When finite: split (largest first) until every subdomain's area is at most this;
  /// `subdomains` is then ignored (3.7).
  double max_subdomain_area = std::numeric_limits<double>::infinity();
  /// r: the refinement factor (4.1), > 0; see madd_refinement_scale.
  double refinement_factor = 4.0;
  /// How the refinement length h of a split is chosen from r: per subdomain (the default) or
  /// globally as the dissertation's static MADD (4.1).
  madd_refinement_scale refinement_scale = madd_refinement_scale::subdomain;
  /// Dynamic MADD (4.1): a split that finds no separator is retried with the boundary
  /// refined for r, 2r, 4r, ...: at most this many levels (>= 1).
  int max_refinement_levels = 8;
  /// A boundary piece is bisected at most this many times for empty diametral circles
  /// (condition (ii) of 3.2; bounded because small input angles cascade).
  int max_encroachment_depth = 8;
  /// Separator smoothing (4.2): angle-quality f0 and conformity f1 weights on the graph
  /// edges before the partition, a local search minimising the weighted separator cost with
  /// the larger part <= max_part_fraction after it (or no larger than the partitioner left
  /// it). Off by default: measured on the pipe, key, Lake Superior and guitar domains (N =
  /// 256) it shortened the separators by 0.1-1% and changed the smallest separator angle by
  /// -1.4..+3.6 degrees. Its local search used to be bounded by L_b (0.75), and its trade of
  /// balance for length raised the largest/mean subdomain area to 1.59-1.69 at N = 64 on Lake
  /// Superior, the guitar, the Bahamas and a 3-element airfoil (1.31-1.48 unsmoothed); bounded
  /// by the partitioner's fraction, 1.29-1.47 (issue 36 item 4).
  bool smoothing = false;
  /// L_b: a split whose larger child exceeds this fraction of the area (into N: whose children
  /// leave a larger area per subdomain than 2 L_b times the region's) is retried with more
  /// refinement (at most two more levels, the best is kept).
  double imbalance_bound = 0.75;
  /// The balance bound given to the graph partitioner (bisection_options). 0.52 (0.55 before
  /// issue 36 item 4): with quotas, the largest/mean area at N = 3-4096 on Lake Superior, the
  /// guitar, Texas, the Bahamas and the 3-element airfoil was at most 1.505 against 1.68 at
  /// 0.55 (0.51 was worse again: 1.56), for 0.2-2% longer separators.
  double max_part_fraction = 0.52;
  /// With max_subdomain_area or a split_policy, a round of concurrent splits (4.3) takes the
  /// subdomains whose area (or priority) is at least this fraction of the largest (largest
  /// first): 1 splits one subdomain at a time, the sequential largest-first order of 3.7;
  /// smaller values give more concurrency and, below the splits' balance, a less even
  /// decomposition. Into N subdomains it is not used: every subdomain gets a quota of the N
  /// (by area; a component of the domain at least 1), a subdomain that is to become q is split
  /// with target shares floor(q/2) : ceil(q/2) and its children's quotas follow their areas, and
  /// a round splits every subdomain whose quota is above 1 (issue 36 item 4).
  double round_fraction = 0.6;
  /// Worker threads for the concurrent splits (4.3); 0: all. The result does not depend on it.
  unsigned threads = 0;
  /// Graded decomposition (4.4, 7.3): when set, it decides which leaves are split and in which
  /// order instead of the area: MADD stops when no leaf has a positive priority or when
  /// `subdomains` leaves exist; max_subdomain_area must then stay infinite. A leaf whose split
  /// fails while its priority stays positive ends pdd::decompose with a decomposition_error
  /// naming it, once nothing else can be split.
  madd_split_policy split_policy{};
  /// General PSLGs: the least distance every separator keeps from the dangling segments and
  /// isolated vertices inside a region (they stay inside one subdomain, see pdd::decompose);
  /// the split's boundary spacing h is kept when larger. A region that no separator can split
  /// so is left whole, like any region MADD cannot split (others are split in its place).
  /// pdd::generate sets it to four times the decoupling path's area term, so that a separator
  /// passing a feature does not lower lfs_min, and with it k, below what the area bound gives,
  /// and decomposes again with h alone when N cannot be reached so. >= 0.
  double feature_clearance = 0.0;
};

} // namespace pdd
