// pdd::graded_subdomain_k: the graded path's k_i without the path (the pipeline caps the graded
// shields with them, dissertation 8.3): equal to decouple_graded's, lowered for relation 7.1.
#include "hand_decompositions.hpp"

#include <pdd/decoupling/graded_decouple.hpp>
#include <pdd/parallel/sequential_executor.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace graded_subdomain_k_test {
namespace {

TEST(GradedSubdomainK, EqualsDecoupleGradedAndLowersForRelation71) {
  const auto c = pdd::test::grid_case(4, 4);
  const std::size_t m = c.parts.subdomains.size();
  pdd::mesh_criteria criteria;
  std::vector<double> lo(m);
  for (std::size_t s = 0; s < m; ++s) { // 8x per column: neighbours' k_j / k_i = 2.8 > sqrt 3
    double x = 0.0;
    for (const pdd::index_t v : c.parts.subdomains[s].loops[0])
      x += c.parts.vertices[v].x / static_cast<double>(c.parts.subdomains[s].loops[0].size());
    lo[s] = 1e-5 * std::pow(8.0, std::floor(4.0 * x));
  }
  const std::vector<double> k = pdd::graded_subdomain_k(c.parts, criteria, lo);
  const pdd::graded_decoupling g = pdd::decouple_graded(c.parts, criteria, lo);
  ASSERT_EQ(k.size(), m);
  EXPECT_EQ(k, g.subdomain_k);
  EXPECT_GT(g.lowered_k, 0u);
  pdd::graded_decoupling_options keep;
  keep.lower_k = false;
  const std::vector<double> unlowered = pdd::graded_subdomain_k(c.parts, criteria, lo, {}, keep);
  std::size_t lower = 0;
  for (std::size_t s = 0; s < m; ++s) {
    EXPECT_LE(k[s], unlowered[s]);
    EXPECT_DOUBLE_EQ(unlowered[s], std::min(0.25 / 4, 0.5 * std::sqrt(lo[s] / std::sqrt(2.0))));
    lower += k[s] < unlowered[s] ? 1 : 0;
  }
  EXPECT_EQ(lower, g.lowered_k);
  EXPECT_THROW((void)pdd::graded_subdomain_k(c.parts, criteria, {1.0}), pdd::decoupling_error);
}

} // namespace

} // namespace graded_subdomain_k_test
