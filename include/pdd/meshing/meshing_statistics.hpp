/// \file meshing_statistics.hpp
/// pdd::meshing_statistics and pdd::subdomain_report: what pdd::mesh_subdomains did.
#pragma once

#include <cstddef>
#include <vector>

namespace pdd {

/// What happened to one subdomain in pdd::mesh_subdomains.
struct subdomain_report {
  /// The subdomain's area, in squared input units.
  double area = 0.0;
  std::size_t vertices = 0;  ///< of its delivered mesh
  std::size_t triangles = 0; ///< of its delivered mesh
  double seconds = 0.0;      ///< kernel + check time, summed over runs
  unsigned runs = 0;         ///< 1, or more after invariance repairs
};

/// Statistics of pdd::mesh_subdomains.
struct meshing_statistics {
  /// Interface pieces found split by the kernel (Corollary 13 says 0).
  std::size_t interface_splits = 0;
  /// Shield edges found split by the kernel (Theorem 24 (5) says 0; a split one throws).
  std::size_t shield_splits = 0;
  /// Subdomain meshings repeated by invariance repairs (0 unless interface_splits > 0).
  std::size_t remeshed_subdomains = 0;
  /// Invariance repair rounds run (each halves k on the failing segments; at most
  /// meshing_options::max_repairs).
  std::size_t repair_rounds = 0;
  std::vector<subdomain_report> subdomains; ///< by subdomain id

  /// Triangles delivered, summed over the subdomains' reports.
  std::size_t triangles() const noexcept {
    std::size_t n = 0;
    for (const auto& s : subdomains)
      n += s.triangles;
    return n;
  }
};

} // namespace pdd
