// Long tests (ctest label "long", not in the default suite: ctest --preset long): the decoupled
// pipeline on the Bahamas (276 islands, a 1.9e-6 segment) from ../shared/data, where the uniform
// k is held at lfs_min = 1.1e-6 and the separators carry millions of split points. Skips when
// ../shared is absent.
#include <pdd/generate.hpp>
#include <pdd/io/poly.hpp>

#include "mesh_compare.hpp"
#include "test_support.hpp"
#include "verified.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace bahamas_test {
TEST(LongShielded, BahamasDecoupledVerifiedAndThreadIndependent) {
  const auto dir = pdd::test::shared_data_dir();
  if (dir.empty() || !std::filesystem::exists(dir / "bahamas_islands.poly"))
    GTEST_SKIP() << "no shared data";
  const auto file = dir / "bahamas_islands.poly";
  const pdd::pslg g = pdd::read_poly(file.string());
  pdd::generate_options o;
  o.criteria.max_area = pdd::domain_area(g) / 3000.0;
  o.subdomains = 2;
  o.threads = 1;
  o.check_memory = false;
  o.geometric_sizing = pdd::geometric_sizing_mode::off; // the uniform path (geometric_bahamas_test)
  const pdd::generate_result one = pdd::generate(g, o);
  EXPECT_EQ(one.statistics.subdomains, 2u);
  EXPECT_GT(one.statistics.split_points, 1000000u); // k = lfs_min: the uniform method's cost
  EXPECT_EQ(one.statistics.interface_splits, 0u);
  EXPECT_EQ(one.statistics.shield_splits, 0u);
  EXPECT_EQ(pdd::test::expect_verified(one.mesh, g, o.criteria, "bahamas N=2"),
            one.statistics.shielded_triangles);
  o.threads = 2;
  EXPECT_TRUE(pdd::test::bitwise_equal(one.mesh, pdd::generate(g, o).mesh)) << "1 vs 2 threads";
}

} // namespace bahamas_test
