// The graded path with Theorem 26's shields end to end (dissertation 8.3): the closed-loop
// ../shared/data geometries (Lake Superior, Texas and the guitar have input angles below 60 deg;
// the three-element airfoil has none), a field graded across the domain and a uniform one,
// N = 16 and 64: the graded path is taken (no fallback), the mesh is verified (exact Delaunay,
// conformity, area <= F, quality of the unshielded triangles), every small input angle is the
// apex angle of its shielded triangle, no interface piece or shield edge was split, and the
// meshes at 1 and 2 threads are bitwise identical. Skips (counting the runs) without ../shared.
#include <pdd/generate.hpp>
#include <pdd/geometry/properties.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/mesh/verify.hpp>
#include <pdd/shielding/shield_statistics.hpp>
#include <pdd/sizing/expression.hpp>

#include "mesh_compare.hpp"
#include "test_support.hpp"
#include "verified.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace graded_shields_pipeline_test {
namespace {

/// F = fine (1 + 30 u^2), u in [0, 1] across the bounding box, or F = fine everywhere.
pdd::any_sizing field(const pdd::pslg& g, double triangles, bool graded) {
  const pdd::bbox b = pdd::bounding_box(g);
  const std::string fine = std::to_string(pdd::domain_area(g) / triangles);
  if (!graded) return pdd::expression_sizing(fine);
  return pdd::expression_sizing(fine + "*(1+30*((x-(" + std::to_string(b.xmin) + "))/" +
                                std::to_string(b.width()) + ")^2)");
}

/// Checks one run (see the file comment); returns the number of small input angles.
std::size_t expect_graded_with_shields(const pdd::pslg& g, pdd::generate_options o,
                                       const std::string& at) {
  SCOPED_TRACE(at);
  o.threads = 1;
  const pdd::generate_result one = pdd::generate(g, o);
  const pdd::generate_statistics& st = one.statistics;
  EXPECT_TRUE(st.graded_path) << st.graded_fallback;
  EXPECT_TRUE(st.graded_fallback.empty()) << st.graded_fallback;
  EXPECT_GE(st.subdomains, o.subdomains);
  EXPECT_EQ(st.interface_splits, 0u);
  EXPECT_EQ(st.shield_splits, 0u);
  const std::size_t small = pdd::detail::small_angle_apexes(g).size();
  EXPECT_EQ(st.shielded_triangles, small);
  pdd::test::expect_verified_shielded(one.mesh, g, o.criteria, o.sizing);
  const pdd::shielding_statistics sh = pdd::compute_shielding_statistics(one.mesh, g);
  EXPECT_EQ(sh.shielded_triangles, small);
  EXPECT_LT(sh.max_shield_angle_error_deg, 1e-6);
  EXPECT_GE(sh.min_angle_unshielded_deg, 20.7 - 1e-9);
  o.threads = 2;
  EXPECT_TRUE(pdd::test::bitwise_equal(one.mesh, pdd::generate(g, o).mesh));
  return small;
}

TEST(GradedShieldsPipeline, RealGeometriesTakeTheGradedPath) {
  const auto dir = pdd::test::shared_data_dir();
  std::size_t runs = 0, shielded = 0;
  for (const char* f : {"lake_superior", "texas", "mesh2d_airfoil_3element", "guitar"}) {
    const auto path = dir / (std::string(f) + ".poly");
    if (dir.empty() || !std::filesystem::exists(path)) continue;
    const pdd::pslg g = pdd::read_poly(path.string());
    for (const bool graded : {true, false})
      for (const std::size_t n : {16u, 64u}) {
        pdd::generate_options o;
        o.sizing = field(g, 6000.0, graded);
        o.subdomains = n;
        const std::string at =
            std::string(f) + (graded ? " graded" : " uniform") + " N " + std::to_string(n);
        shielded += expect_graded_with_shields(g, o, at) > 0 ? 1 : 0;
        ++runs;
      }
  }
  RecordProperty("runs", static_cast<int>(runs));
  RecordProperty("shielded_runs", static_cast<int>(shielded));
  if (dir.empty()) GTEST_SKIP() << "../shared/data absent: 0 runs";
  EXPECT_EQ(runs, 16u);
  EXPECT_EQ(shielded, 12u); // the airfoil has no input angle below 60 deg
}

// decoupling.k_scale still takes the interim uniform path (with the uniform shields), and says so.
TEST(GradedShieldsPipeline, KScaleStillFallsBackWithShields) {
  const auto dir = pdd::test::shared_data_dir();
  const auto path = dir / "lake_superior.poly";
  if (dir.empty() || !std::filesystem::exists(path)) GTEST_SKIP() << "../shared/data absent";
  const pdd::pslg g = pdd::read_poly(path.string());
  pdd::generate_options o;
  o.sizing = field(g, 6000.0, true);
  o.subdomains = 16;
  o.threads = 2;
  o.decoupling.k_scale = 0.5;
  const pdd::generate_result r = pdd::generate(g, o);
  EXPECT_FALSE(r.statistics.graded_path);
  EXPECT_NE(r.statistics.graded_fallback.find("k_scale"), std::string::npos);
  EXPECT_EQ(r.statistics.shielded_triangles, pdd::detail::small_angle_apexes(g).size());
  pdd::test::expect_verified_shielded(r.mesh, g, o.criteria, o.sizing);
}

} // namespace

} // namespace graded_shields_pipeline_test
