/// \file graded_shields.hpp
/// The shields of the graded decoupling method (dissertation 8.3, Theorem 26): per subdomain
/// D_i the length l_i = (cos(Phi_i/2) + sin Phi_i) / 2 sqrt(m_F(D_i) / sqrt 2) from the sizing
/// field's lower bound over D_i, with the safeguards of the uniform shields.
#pragma once

#include <pdd/concepts/executor.hpp>
#include <pdd/core/decomposition.hpp>
#include <pdd/errors.hpp>
#include <pdd/parallel/sequential_executor.hpp>
#include <pdd/shielding/detail/plan.hpp>
#include <pdd/shielding/subdomain_shields.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace pdd {

/// Theorem 26's shield length l_i = (cos(Phi/2) + sin Phi) / 2 sqrt(m_F / sqrt 2), Phi (degrees)
/// the largest angle < 60 deg of the subdomain, m_F = m_F(D_i) the field's minimum over it.
/// Since cos(x/2) + sin x rises from 1 at 0 to sqrt 3 at 60 deg, every shield edge of D_i has
/// k_F <= |b'c'| = l_i / (cos(theta/2) + sin theta) < sqrt 3 k_F, k_F = (1/2) sqrt(m_F / sqrt 2)
/// (Theorem 26 (b), (c)). Infinity when m_F is. Complexity O(1).
inline double graded_shield_length(double phi_deg, double m_F) {
  const double r = phi_deg * std::numbers::pi / 180.0;
  return (std::cos(r / 2.0) + std::sin(r)) / 2.0 * std::sqrt(m_F / std::numbers::sqrt2);
}

/// l_i of one subdomain with small angles theta (per loop, degrees, 0: not shielded), lfs_min
/// `lfs`, field minimum m_F and cap `max_l`: the minimum of
/// - Theorem 26's graded_shield_length(Phi_i, m_F), Phi_i = max theta;
/// - eq. 8.6's terms with A = m_F: (1 + 2 sin(theta/2)) sqrt(2 m_F sin theta) for every theta,
///   sqrt(m_F / sqrt 2) (never the smallest: Theorem 26's term is below it) and lfs_min(D_i);
/// - max_l (the pipeline passes shield_length_cap(k_i), k_i the unshielded subdomain's graded
///   decoupling parameter);
/// less one part in 1e9 (shielded triangle areas stay <= m_F after rounding).
/// Where this differs from the text: Theorem 26 proves l_i <= lfs_min(D_i) and the shielded
/// triangles' area <= m_f(D_i) from condition (ii) of the field F of Algorithm 8.3
/// (m_F(D_i) <= 4 sqrt 2 e_i^2, e_i of relation 8.10). Any field may reach the graded path here
/// (the user's own, or F before Algorithm 8.3 shrank it), so those two bounds are enforced
/// directly, as in Algorithm 8.2: the terms of eq. 8.6. For a field that meets condition (ii)
/// they do not bind, and l_i is Theorem 26's. The cap sqrt 3 k_i is the uniform path's
/// safeguard (see pdd::shield_decomposition): the kernel meshes D_i' with ratio bound B and
/// k_i = min(lfs_min(D_i), sqrt 3 L_i / 4, (1/2) sqrt(m_F / max(B, sqrt 2))) (Theorem 15's terms
/// per subdomain, L_i its shortest separator segment); Theorem 26 has only the area term with B =
/// sqrt 2, and l_i <= sqrt 3 k_i keeps |b'c'| < 2 k_i, the length Proposition 20 lets Ruppert-type
/// refinement keep, where lfs_min, a short separator or B > sqrt 2 hold k_i below k_F. Where a
/// safeguard binds, |b'c'| may fall below k_F (Theorem 26 (c)): the decoupling path is then built
/// for lfs_min(D_i') (k_i is recomputed on the shielded subdomain), which only shortens D_i's
/// interface pieces. Complexity O(number of angles).
inline double graded_subdomain_shield_length(const std::vector<std::vector<double>>& theta,
                                             double lfs, double m_F, double max_l) {
  double phi = 0.0;
  for (const auto& loop : theta)
    for (const double t : loop)
      phi = std::max(phi, t);
  double l = std::min(max_l, detail::shield_length(theta, lfs, m_F));
  if (std::isfinite(m_F)) l = std::min(l, graded_shield_length(phi, m_F) * (1.0 - 1e-9));
  return l;
}

/// Shields the small angles of every subdomain of d in place (Algorithm 8.2 with Theorem 26's
/// l_i, see graded_subdomain_shield_length and pdd::shield_subdomains): subdomain i with
/// m_F(D_i) = area_lower_bound[i] (a TRUE lower bound of the area bound over D_i, already
/// combined with criteria.max_area; infinity: none) and cap max_l[i]. Each shield lies in the
/// subdomain that holds its small-angle vertex, built from that subdomain's own bound.
/// \throws pdd::decomposition_error when the vectors do not have one value per subdomain, or as
/// pdd::shield_subdomains. Complexity and determinism as pdd::shield_subdomains.
template <Executor E = sequential_executor>
std::vector<subdomain_shields>
shield_graded_decomposition(decomposition& d, const std::vector<double>& area_lower_bound,
                            const E& executor, const std::vector<double>& max_l) {
  const std::size_t m = d.subdomains.size();
  if (area_lower_bound.size() != m || max_l.size() != m)
    throw decomposition_error(
        "shield_graded_decomposition: " + std::to_string(area_lower_bound.size()) +
        " area bounds and " + std::to_string(max_l.size()) + " caps for " + std::to_string(m) +
        " subdomains");
  return shield_subdomains(
      d, executor, [&](std::size_t s, const std::vector<std::vector<double>>& theta, double lfs) {
        return graded_subdomain_shield_length(theta, lfs, area_lower_bound[s], max_l[s]);
      });
}

} // namespace pdd
