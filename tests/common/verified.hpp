// The one "this mesh is what the method promises" check of the tests: pdd::verify with exact
// predicates (global Delaunay, orientation, conformity, area conservation, quality and the area
// bound), quality checked on the triangles that are not shielded (dissertation 8.1), their
// smallest angle >= 20.7 deg, every shielded triangle's apex angle equal to the input angle.
#pragma once

#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/mesh/quality.hpp>
#include <pdd/mesh/verify.hpp>
#include <pdd/shielding/shield_statistics.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace pdd::test {

/// The counters of a verification report on one line, for failure messages.
inline std::string describe(const verification_report& rep) {
  return "delaunay " + std::to_string(rep.delaunay_violations) + " orientation " +
         std::to_string(rep.orientation_violations) + " missing " +
         std::to_string(rep.missing_segments) + " duplicates " +
         std::to_string(rep.duplicate_vertices) + " quality " +
         std::to_string(rep.quality_violations) + " area " + std::to_string(rep.area_violations) +
         " nonmanifold " + std::to_string(rep.nonmanifold_edges) + " area " +
         std::to_string(rep.area_mesh) + " vs " + std::to_string(rep.area_domain) +
         (rep.messages.empty() ? "" : "\n" + rep.messages.front());
}

/// pdd::verify of m against d, `criteria` and the area bound of `sizing`, with quality checked
/// on the triangles that are not shielded only; expects the mesh conforming, globally Delaunay
/// and within the area bound (`at` names the case in failure messages).
template <class Sizing>
verification_report expect_verified_shielded(const triangle_mesh& m, const pslg& d,
                                             const mesh_criteria& criteria, const Sizing& sizing,
                                             const std::string& at = {}) {
  verify_options vo{.criteria = criteria};
  vo.quality_exempt = find_shielded_triangles(m, d);
  verification_report rep = verify(m, d, vo, sizing);
  EXPECT_TRUE(rep.ok()) << at << ": " << describe(rep);
  EXPECT_EQ(rep.delaunay_violations, 0u) << at;
  EXPECT_EQ(rep.area_violations, 0u) << at;
  return rep;
}

/// Expects m to be a verified mesh of d under `criteria` (see the file comment); `at` names the
/// case in failure messages. Returns the shielded triangle count.
inline std::size_t expect_verified(const triangle_mesh& m, const pslg& d,
                                   const mesh_criteria& criteria, const std::string& at = {}) {
  verify_options vo{.criteria = criteria};
  vo.quality_exempt = find_shielded_triangles(m, d);
  const verification_report rep = verify(m, d, vo);
  EXPECT_TRUE(rep.ok()) << at << ": " << describe(rep);
  EXPECT_EQ(rep.delaunay_violations, 0u) << at;
  const shielding_statistics sh = compute_shielding_statistics(m, d);
  EXPECT_GE(sh.min_angle_unshielded_deg, std::min(criteria.min_angle_deg, 20.7) - 1e-9) << at;
  EXPECT_LT(sh.max_shield_angle_error_deg, 1e-6) << at;
  EXPECT_LE(compute_statistics(m).max_area, criteria.max_area) << at;
  return sh.shielded_triangles;
}

} // namespace pdd::test
