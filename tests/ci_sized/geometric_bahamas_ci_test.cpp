// CI-sized (ctest label "ci": the release preset runs it, the sanitizer presets do not build
// it) version of tests/long/geometric_bahamas_test.cpp: the Bahamas (276 islands, a 1.9e-6
// segment) at --max-area 4.8e-5 (about 2M triangles; at 1M the split points exceed 5 % of the
// mesh and it is meshed whole) in automatic mode takes the geometric path (Algorithm 8.3's
// loop), decouples within the split-point limit, is verified against the field used, is bitwise
// identical at 1 and 2 threads (the automatic N is the same for both here: 2M / 60K > 4 per
// thread), and stays within 10 % of the monolithic kernel's triangle count (measured +7.1 %; the
// over-refinement falls with the mesh size: +2.5 % at 5M in the long test).
// Skips when ../shared is absent.
#include <pdd/io/poly.hpp>

#include "geometric_verified.hpp"
#include "mesh_compare.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace geometric_bahamas_ci_test {

TEST(CiSizedGeometric, BahamasAt2MDecouplesVerifiedAndThreadIndependent) {
  const auto path = pdd::test::bahamas_path();
  if (path.empty()) GTEST_SKIP() << "no shared data: 0 runs checked";
  const pdd::pslg g = pdd::read_poly(path.string());
  pdd::generate_options o;
  o.criteria.max_area = 4.8e-5;
  o.threads = 2;
  pdd::generate_statistics st;
  const pdd::triangle_mesh two = pdd::test::mesh_verified(g, o, st);
  EXPECT_EQ(st.path, "geometric") << st.plan_reason;
  EXPECT_NE(st.plan_reason.find("Algorithm 8.3"), std::string::npos) << st.plan_reason;
  EXPECT_GT(st.subdomains, 16u);
  EXPECT_LE(static_cast<double>(st.split_points),
            o.planning.max_split_point_fraction * st.estimated_triangles);
  o.threads = 1;
  pdd::generate_statistics st1;
  EXPECT_TRUE(pdd::test::bitwise_equal(two, pdd::test::mesh_verified(g, o, st1)))
      << "1 vs 2 threads";
  o.subdomains = 1;
  pdd::generate_statistics whole;
  const double ratio = static_cast<double>(two.triangles.size()) /
                       static_cast<double>(pdd::test::mesh_verified(g, o, whole).triangles.size());
  std::printf("bahamas 2M: %zu subdomains, %zu split points, %zu triangles, %.2f %% over\n",
              st.subdomains, st.split_points, two.triangles.size(), 100.0 * (ratio - 1.0));
  EXPECT_LT(ratio, 1.10) << "decoupled vs monolithic triangles";
}

} // namespace geometric_bahamas_ci_test
