/// \file quality_exemptions.hpp
/// pdd's one rule for the triangles of a mesh that may stay below the angle bound, applied by
/// pdd::verify by default, by pdd::check_quality and pdd::quality_check_sink on every mesh pdd
/// makes, and by pdd::verify_pieces on the pieces of a streamed mesh: one verdict everywhere.
#pragma once

#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/geometry/validate.hpp>
#include <pdd/mesh/cluster_exempt.hpp>
#include <pdd/shielding/shield_statistics.hpp>

#include <cstddef>
#include <vector>

namespace pdd {

/// Which triangles of a mesh of `domain` (or of a piece of it: one subdomain's mesh) are exempt
/// from the angle bound, found once per domain for many meshes:
/// - a domain of closed loops (pdd::has_closed_loops; the decoupled pipeline shields its input
///   angles < 60 deg, dissertation 8.1): the shielded triangles (pdd::find_shielded_triangles);
///   above Ruppert's bound (pdd::within_ruppert_bound), where pdd meshes such a domain whole
///   and unshielded, also the triangles the kernels' own small-angle rules leave
///   (pdd::find_cluster_exempt_triangles);
/// - any other domain, read by Triangle's rule (the kernel meshes its faces with CGAL's
///   clusters at small angles between segments): the cluster triangles
///   (pdd::find_cluster_exempt_triangles).
/// The domain is taken as meshed: pass pdd::domain_as_generated of a user's PSLG.
/// Thread-safe after construction.
class quality_exemptions {
public:
  /// \throws geometry_error as pdd::validate. Complexity O(n log n).
  explicit quality_exemptions(const pslg& domain)
      : domain_(domain),
        general_(domain.rule == domain_rule::triangle && !has_closed_loops(domain)) {
    if (!general_) angles_ = find_small_input_angles(domain);
  }

  /// Per triangle of m: 1 when it is exempt from the angle bound min_angle_deg.
  std::vector<char> operator()(const triangle_mesh& m, double min_angle_deg) const {
    if (general_) return find_cluster_exempt_triangles(m, domain_, min_angle_deg);
    std::vector<char> exempt = find_shielded_triangles(m, angles_);
    if (within_ruppert_bound(min_angle_deg) || angles_.apexes.empty()) return exempt;
    const std::vector<char> cluster = find_cluster_exempt_triangles(m, domain_, min_angle_deg);
    for (std::size_t t = 0; t < exempt.size(); ++t)
      exempt[t] = exempt[t] || cluster[t];
    return exempt;
  }

  /// The domain's small input angles (closed loops; empty for another domain).
  const small_input_angles& angles() const noexcept { return angles_; }

private:
  pslg domain_;
  bool general_ = false; ///< not one of closed loops (Triangle's rule)
  small_input_angles angles_;
};

/// The triangles of m, a mesh of `domain` as meshed, exempt from the angle bound
/// (quality_exemptions). \throws geometry_error as pdd::validate.
inline std::vector<char> find_quality_exempt_triangles(const triangle_mesh& m, const pslg& domain,
                                                       double min_angle_deg) {
  return quality_exemptions(domain)(m, min_angle_deg);
}

} // namespace pdd
