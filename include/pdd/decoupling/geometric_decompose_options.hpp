/// \file geometric_decompose_options.hpp
/// pdd::geometric_decompose_options: the bounds of the geometric loop (pdd::geometric_decompose),
/// apart from it so that pdd::generate_options can hold them without the loop's code.
#pragma once

#include <cstddef>

namespace pdd {

/// Bounds of the loop (designated initialisers welcome).
struct geometric_decompose_options {
  /// Stop when the estimated over-refinement (geometric_sizing_result::over_refinement) is at
  /// most this.
  double target_over_refinement = 0.03;
  /// At most this many rounds of decomposition + Algorithm 8.3 (the first is the given one).
  unsigned max_rounds = 4;
  /// At most this many subdomains in a refined round (Algorithm 7.1's max_subdomains).
  std::size_t max_subdomains = 4096;
  /// Tiny features the first refined round grades towards; x8 per further round.
  std::size_t first_feature_cap = 128;
  /// The driver's growth of the feature size per unit of distance in the first refined round
  /// (pdd::feature_driven_sizing); divided by 4 in each further round.
  /// Why 1/32 (was 1/4) and 128 (was 64): a slower growth carries the small subdomains
  /// farther out, so the subdomains where the driver meets the user's bound are wide enough
  /// for the area term of k_i, and fewer rings of relation 7.1 hold k_i below it. Measured
  /// (benchmarks/results/real-geometries.md, benchmarks/run_geometric_history.sh): the Bahamas
  /// at 2M / 5M / 20M triangles +7.1 / +2.4 / +0.85 % over the monolithic kernel (1/4 and 64:
  /// +11.4 / +4.0 / +0.98 %), the airfoil at 1M +4.4 % (+5.4 %), Texas at 300K +2.3 % (+3.3 %).
  double first_slope = 1.0 / 32.0;
};

} // namespace pdd
