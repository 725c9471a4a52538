/// \file gradation_options.hpp
/// pdd::gradation_options: the options of the gradation-controlled decomposition
/// (dissertation 7.3, Algorithm 7.1; Condition 3 of 7.6), and their check.
#pragma once

#include <pdd/errors.hpp>
#include <pdd/sizing/sizing_range.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>

namespace pdd {

/// Options of Algorithm 7.1 (designated initialisers welcome).
struct gradation_options {
  /// R1 of Condition 1: M(D_i) <= R1 m(D_i) for every subdomain.
  double r1 = 1.425;
  /// R2 of Condition 2: m(D_i) <= R2 m(D_j) for every two subdomains sharing a separator;
  /// R1 <= R2 < 3 (7.3; R2 < 3 gives k_j / k_i < sqrt 3, the existence of the decoupling
  /// path, 7.4).
  double r2 = 1.5;
  /// T of Condition 3 (7.6): at most this many expected triangles per subdomain (load
  /// balance and memory); infinity: no Condition 3.
  double max_subdomain_triangles = std::numeric_limits<double>::infinity();
  /// Termination rule: a subdomain that expects fewer triangles than this is not split for
  /// Conditions 1-2 (a field with a jump of ratio > R2, as the piecewise constant .poly
  /// regional areas, meets Condition 2 for no decomposition; the decoupling path then lowers
  /// k where relation 7.1 needs it, pdd::decouple_graded). 0: split until the conditions hold.
  double min_subdomain_triangles = 1000.0;
  /// At least this many subdomains: while fewer exist every subdomain is split, the largest
  /// expected work first (a requested N).
  std::size_t min_subdomains = 1;
  /// At most this many subdomains (MADD's `subdomains`): the decomposition stops there, and
  /// gradation_report::capped says that some subdomain was still non-acceptable.
  std::size_t max_subdomains = 100000;
  /// A uniform area bound combined with the field: m and M are taken of min(max_area, F).
  double max_area = std::numeric_limits<double>::infinity();
  /// The mean triangle area as a fraction of the bound (pdd::mean_triangle_area_fraction):
  /// expected triangles of D = integral over D of 1 / (fraction * min(max_area, F)).
  double mean_area_fraction = 0.656;
  /// How m(D) and M(D) are taken of a field without range() (pdd::sizing_range's grid rule):
  /// at most 64 cells a side, and no finer than the mesh the field asks for
  /// (sizing_range_options::mesh_resolution = 1). MADD's leaves are small: a 64 x 64 grid over
  /// a leaf expecting 1000 triangles cost four evaluations of F per triangle.
  sizing_range_options range{.cells = 64, .mesh_resolution = 1.0};
};

/// \throws pdd::decomposition_error naming the field: R1 <= 1, R2 < R1 or R2 >= 3, T <= 0,
/// a negative minimum, max_subdomains < max(1, min_subdomains), max_area <= 0, the
/// fraction outside (0, 1], or a grid rule (range) with < 2 cells or a negative resolution.
inline void check_gradation_options(const gradation_options& o) {
  const auto bad = [](const std::string& what) {
    throw decomposition_error("gradation_options: " + what);
  };
  if (!(o.r1 > 1.0) || !std::isfinite(o.r1)) bad("r1 must be > 1 (Condition 1)");
  if (!(o.r2 >= o.r1 && o.r2 < 3.0))
    bad("r2 = " + std::to_string(o.r2) +
        " must satisfy r1 <= r2 < 3 (7.3: the gradation inside a "
        "subdomain at most that across a separator; 7.4: r2 < 3 for k_j / k_i < sqrt 3)");
  if (!(o.max_subdomain_triangles > 0.0)) bad("max_subdomain_triangles (T) must be > 0");
  if (!(o.min_subdomain_triangles >= 0.0) || !std::isfinite(o.min_subdomain_triangles))
    bad("min_subdomain_triangles must be finite and >= 0");
  if (o.max_subdomains < std::max<std::size_t>(1, o.min_subdomains))
    bad("max_subdomains must be >= max(1, min_subdomains)");
  if (!(o.max_area > 0.0)) bad("max_area must be > 0");
  if (o.range.cells < 2 || !(o.range.mesh_resolution >= 0.0) ||
      !std::isfinite(o.range.mesh_resolution))
    bad("range: cells must be >= 2 and mesh_resolution finite and >= 0");
  if (!(o.mean_area_fraction > 0.0 && o.mean_area_fraction <= 1.0))
    bad("mean_area_fraction must be in (0, 1]");
}

} // namespace pdd
