// N-way MADD on generated domains: exact subdomain counts, valid polygons, conforming
// interfaces, separator angles >= Phi0, areas, determinism across thread counts.
#include <pdd/geometry/model_domains.hpp>
#include <pdd/madd/decompose.hpp>
#include <pdd/madd/validate_decomposition.hpp>

#include <test_support.hpp>

#include <gtest/gtest.h>

namespace {

pdd::pslg square(double s = 1.0) {
  pdd::pslg g;
  g.add_loop(std::vector<pdd::point>{{0, 0}, {s, 0}, {s, s}, {0, s}}, 1);
  return g;
}

void expect_valid(const pdd::decomposition& d, const pdd::pslg& g, std::size_t n,
                  double phi0 = 60.0) {
  EXPECT_EQ(d.subdomains.size(), n);
  const auto rep = pdd::validate_decomposition(d, g, {.min_angle_deg = phi0});
  EXPECT_TRUE(rep.ok()) << rep.summary();
}

TEST(MaddDecompose, SquareTwoWay) {
  const auto g = square();
  pdd::decomposition_statistics st;
  const auto d = pdd::decompose(g, {.subdomains = 2}, pdd::default_partitioner{}, &st);
  expect_valid(d, g, 2);
  EXPECT_GE(st.min_separator_angle_deg, 60.0 - 1e-9);
}

TEST(MaddDecompose, PipeManyWays) {
  const auto g = pdd::pipe_domain();
  for (std::size_t n : {2u, 7u, 64u}) {
    pdd::decomposition_statistics st;
    const auto d = pdd::decompose(g, {.subdomains = n}, pdd::default_partitioner{}, &st);
    expect_valid(d, g, n);
    std::printf("n=%zu time %.3f s, min angle %.2f, max/mean %.3f, sep %.3f, levels %zu\n", n,
                st.time_s, st.min_separator_angle_deg, st.max_area_over_mean,
                st.separator_length_total, st.levels_tried);
  }
}

} // namespace
