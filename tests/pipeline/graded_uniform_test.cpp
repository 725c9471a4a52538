// The graded decoupling path under a uniform area bound (no field): one k_i per subdomain
// (Theorem 22 with m(D_i) = max_area), so a small feature or a short separator holds k down
// only in the subdomains beside it. Verified, bitwise the same on 1 and 2 threads, and far
// closer to the monolithic mesh than one global k made it (measured: the notched square at
// N = 64, 2.26x the monolithic triangles with one k, 1.17x with k_i; the airfoil at N = 256,
// 1.56x and 1.04x).
#include "mesh_compare.hpp"
#include "test_support.hpp"
#include "verified.hpp"

#include <pdd/generate.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/pipeline.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace graded_uniform_test {
namespace {

using pdd::point;

/// The unit square with a notch 1e-4 wide and deep in its bottom side.
pdd::pslg notched_square() {
  pdd::pslg g;
  g.add_loop(std::vector<point>{
      {0, 0}, {0.5, 0}, {0.5, 1e-4}, {0.5001, 1e-4}, {0.5001, 0}, {1, 0}, {1, 1}, {0, 1}});
  return g;
}

pdd::generate_options options(double max_area, std::size_t n, unsigned threads) {
  pdd::generate_options o;
  o.criteria.max_area = max_area;
  o.subdomains = n;
  o.threads = threads;
  o.geometric_sizing = pdd::geometric_sizing_mode::off; // N-way MADD, the field alone
  return o;
}

/// Meshes g at N subdomains on 1 and 2 threads, verified; expects the graded path with k_i
/// varying by at least `k_spread` and at most `max_ratio` times the monolithic triangles.
void expect_local_k(const pdd::pslg& g, double max_area, std::size_t n, double k_spread,
                    double max_ratio, const std::string& at) {
  SCOPED_TRACE(at);
  const pdd::generate_result whole = pdd::generate(g, options(max_area, 1, 1));
  const pdd::generate_result one = pdd::generate(g, options(max_area, n, 1));
  const pdd::generate_statistics& st = one.statistics;
  EXPECT_EQ(st.path, "graded");
  EXPECT_TRUE(st.graded_path);
  EXPECT_EQ(st.subdomains, n);
  ASSERT_EQ(st.subdomain_k.size(), n);
  const auto [lo, hi] = std::minmax_element(st.subdomain_k.begin(), st.subdomain_k.end());
  EXPECT_DOUBLE_EQ(st.k, *lo);
  EXPECT_GE(*hi / *lo, k_spread);
  EXPECT_EQ(st.interface_splits, 0u);
  pdd::test::expect_verified(one.mesh, g, options(max_area, n, 1).criteria, at);
  const double ratio = static_cast<double>(one.mesh.triangles.size()) /
                       static_cast<double>(whole.mesh.triangles.size());
  EXPECT_LT(ratio, max_ratio) << one.mesh.triangles.size() << " vs monolithic "
                              << whole.mesh.triangles.size();
  const pdd::generate_result two = pdd::generate(g, options(max_area, n, 2));
  EXPECT_TRUE(pdd::test::bitwise_equal(one.mesh, two.mesh));
}

} // namespace

TEST(GradedUniform, ATinyNotchLowersKOnlyBesideIt) {
  // one global k (the notch's 1e-4) made 2.26x the monolithic triangles here
  expect_local_k(notched_square(), 5e-6, 64, 5.0, 1.3, "notched square N = 64");
}

TEST(GradedUniform, TheAirfoilsNarrowGapsLowerKOnlyBesideThem) {
  const auto dir = pdd::test::shared_data_dir();
  const auto file = dir / "mesh2d_airfoil_3element.poly";
  if (dir.empty() || !std::filesystem::exists(file)) GTEST_SKIP() << "../shared/data absent";
  // one global k made 1.56x the monolithic triangles at N = 256
  expect_local_k(pdd::read_poly(file.string()), 3e-6, 256, 2.0, 1.1, "airfoil N = 256");
}

TEST(GradedUniform, ASetKStillTakesTheUniformPath) {
  pdd::generate_options o = options(5e-6, 16, 1);
  o.decoupling.k_scale = 0.5;
  const pdd::generate_result r = pdd::generate(notched_square(), o);
  EXPECT_EQ(r.statistics.path, "uniform");
  EXPECT_FALSE(r.statistics.graded_path);
  EXPECT_NE(r.statistics.graded_fallback.find("k_scale"), std::string::npos);
  pdd::test::expect_verified(r.mesh, notched_square(), o.criteria, "k_scale 0.5");
}

} // namespace graded_uniform_test
