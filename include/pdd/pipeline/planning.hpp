/// \file planning.hpp
/// The pipeline's planning rules: the triangle estimate, the automatic number of subdomains
/// and the peak memory estimate.
#pragma once

#include <pdd/core/mesh_criteria.hpp>
#include <pdd/pipeline/options.hpp>
#include <pdd/sizing/mesh_size_estimate.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace pdd {

/// Expected triangle count of a uniform mesh of a domain of the given area under bound A:
/// area / (0.656 A) (pdd::mean_triangle_area_fraction); infinity when A is not finite. The
/// pipeline plans with pdd::estimate_mesh_size instead, which also bounds the triangle size by
/// the local feature size; this is its value where no feature is smaller than the mesh.
/// Complexity O(1).
inline double estimate_triangles(double domain_area, const mesh_criteria& criteria) {
  if (!std::isfinite(criteria.max_area)) return std::numeric_limits<double>::infinity();
  return domain_area / (mean_triangle_area_fraction * criteria.max_area);
}

/// The automatic number of subdomains for an expected mesh of E triangles on P threads.
///
/// The kernel's cost per triangle grows with the size of what it meshes (pdd::cgal::mesher
/// with its heap queue, one core, unit square: 1.7 us/triangle at 19K triangles, 1.8 at 75K,
/// 2.2 at 250K, 2.9 at 1M, 3.5 at 4M), so even one thread gains from meshing small subdomains
/// (key domain, 4.5M triangles, one thread: 17.1 s monolithic, 5.0-5.2 s with N = 75-220,
/// MADD 30-50 ms); the dissertation's rule (6.4) is N >= E / 1.6M for Triangle, whose curve is
/// much flatter. We take N = max(ceil(E / target), min_per_thread * P) (the second term only
/// for P > 1: over-decomposition for load balance, 6.4), capped at E / min_triangles, and
/// N = 1 (the kernel on the whole domain) when that leaves fewer than 2 subdomains or E is
/// not finite (no area bound). target = o.target_subdomain_triangles (default 60K),
/// min_per_thread = o.min_subdomains_per_thread (4), min_triangles = o.min_subdomain_triangles
/// (5K). The defaults are a first choice to be tuned by benchmarks (benchmarks/results).
/// Complexity O(1).
inline std::size_t automatic_subdomains(double estimated_triangles, unsigned threads,
                                        const planning_options& o) {
  if (!std::isfinite(estimated_triangles) || estimated_triangles <= 0.0) return 1;
  double n = std::ceil(estimated_triangles / std::max(1.0, o.target_subdomain_triangles));
  if (threads > 1) n = std::max(n, static_cast<double>(o.min_subdomains_per_thread) * threads);
  n = std::min(n, std::floor(estimated_triangles / std::max(1.0, o.min_subdomain_triangles)));
  return n < 2.0 ? 1 : static_cast<std::size_t>(std::min(n, 1e7));
}

/// Estimated peak memory (bytes) of meshing E triangles as N subdomains on P threads: the
/// kernel's working set for the subdomains in flight (CGAL: about 150-170 bytes per triangle
/// at its peak, output included; 1.3 x the mean subdomain for size variation) plus, when the
/// sink keeps the meshes, the stored subdomain meshes and the merged mesh (about 26 bytes per
/// triangle each: 16 for the triangle and its marker, 10 for half a vertex). N = 1: the
/// kernel on everything. Complexity O(1).
inline double estimate_peak_bytes(double triangles, std::size_t subdomains, unsigned threads,
                                  bool retains_meshes) {
  constexpr double kernel_bytes = 170.0, mesh_bytes = 26.0;
  if (subdomains <= 1) return triangles * kernel_bytes;
  const double n = static_cast<double>(subdomains);
  const double in_flight = std::min<double>(std::max(1u, threads), n) * 1.3 * (triangles / n);
  return in_flight * kernel_bytes + (retains_meshes ? 2.0 * triangles * mesh_bytes : 0.0);
}

} // namespace pdd
