// The shields of the graded method (dissertation 8.3, Theorem 26): l_i against hand-computed
// values, its safeguards (eq. 8.6 terms, lfs_min, the cap), and shields placed per subdomain of
// a decomposition from each subdomain's own area bound.
#include "test_support.hpp"

#include <pdd/core/triangle_measures.hpp>
#include <pdd/madd/decompose.hpp>
#include <pdd/shielding/graded_shields.hpp>
#include <pdd/shielding/shield_decomposition.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace graded_shields_test {
namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// (cos(Phi/2) + sin Phi) / 2 * sqrt(m / sqrt 2), computed by hand:
// Phi 30, m 1: (0.96592583 + 0.5) / 2 * 0.84089642 = 0.61634589
// Phi 45, m 4: (0.92387953 + 0.70710678) / 2 * 1.68179283 = 1.37149054
TEST(GradedShields, LengthOfTheorem26AgainstHandValues) {
  EXPECT_NEAR(pdd::graded_shield_length(30.0, 1.0), 0.6163458861771585, 1e-15);
  EXPECT_NEAR(pdd::graded_shield_length(45.0, 4.0), 1.371490544516379, 1e-15);
  EXPECT_NEAR(pdd::graded_shield_length(30.0, 4.0), 1.232691772354317, 1e-15);
  EXPECT_NEAR(pdd::graded_shield_length(45.0, 1.0), 0.6857452722581895, 1e-15);
  // between k_F and sqrt 3 k_F, k_F = (1/2) sqrt(m / sqrt 2)
  const double kf = 0.5 * std::sqrt(1.0 / std::numbers::sqrt2);
  EXPECT_NEAR(pdd::graded_shield_length(0.0, 1.0), kf, 1e-15);
  EXPECT_NEAR(pdd::graded_shield_length(60.0, 1.0), std::numbers::sqrt3 * kf, 1e-15);
}

TEST(GradedShields, SafeguardsOfTheSubdomainLength) {
  const double shrink = 1.0 - 1e-9;
  // Theorem 26's term binds: Phi = 45 is the largest small angle
  EXPECT_DOUBLE_EQ(pdd::graded_subdomain_shield_length({{0, 30, 0}, {45}}, 10.0, 1.0, inf),
                   0.6857452722581895 * shrink);
  // theta = 5: the area term (1 + 2 sin 2.5) sqrt(2 m sin 5) = 0.45392901 of eq. 8.6 binds
  EXPECT_NEAR(pdd::graded_subdomain_shield_length({{5, 30}}, 10.0, 1.0, inf),
              0.45392900544499 * shrink, 1e-14);
  // lfs_min and the cap
  EXPECT_DOUBLE_EQ(pdd::graded_subdomain_shield_length({{30}}, 0.25, 1.0, inf), 0.25 * shrink);
  EXPECT_DOUBLE_EQ(pdd::graded_subdomain_shield_length({{30}}, 10.0, 1.0, 0.125), 0.125);
  // no area bound: lfs_min
  EXPECT_DOUBLE_EQ(pdd::graded_subdomain_shield_length({{30}}, 0.5, inf, inf), 0.5);
}

// A 16-spike star in 8 subdomains, each with its own m(D_i): every shield is built from the
// bound of the subdomain that holds its apex (area <= m_i, |b'c'| >= k_F(m_i) where Theorem
// 26's term binds, < sqrt 3 k_F always), and the executor does not change the result.
TEST(GradedShields, PerSubdomainBounds) {
  const pdd::pslg g = pdd::test::star_polygon(16, 0.6);
  pdd::madd_options mo;
  mo.subdomains = 8;
  const pdd::decomposition d0 = pdd::decompose(g, mo);
  const std::size_t m = d0.subdomains.size();
  std::vector<double> lo(m), cap(m, inf);
  for (std::size_t s = 0; s < m; ++s)
    lo[s] = 1e-3 * static_cast<double>(1 + s % 3);
  pdd::decomposition d = d0;
  const auto sh = pdd::shield_graded_decomposition(d, lo, pdd::sequential_executor{}, cap);
  std::size_t triangles = 0, binding = 0;
  for (std::size_t s = 0; s < m; ++s) {
    const double kf = 0.5 * std::sqrt(lo[s] / std::numbers::sqrt2);
    for (const pdd::shield_triangle& t : sh[s].triangles) {
      ++triangles;
      EXPECT_LE(pdd::detail::triangle_area(t.apex, t.b, t.c), lo[s]) << s;
      const double bc = std::hypot(t.b.x - t.c.x, t.b.y - t.c.y);
      EXPECT_LT(bc, std::numbers::sqrt3 * kf) << s;
      if (sh[s].l < sh[s].lfs_min * (1 - 1e-9)) {
        ++binding;
        EXPECT_GE(bc, kf * (1 - 1e-8)) << s;
      }
    }
  }
  EXPECT_EQ(triangles, 16u); // one per spike
  EXPECT_GT(binding, 0u);
  pdd::decomposition d2 = d0;
  const auto sh2 = pdd::shield_graded_decomposition(d2, lo, pdd::sequential_executor{}, cap);
  EXPECT_EQ(d.vertices.size(), d2.vertices.size());
  EXPECT_EQ(sh2[0].l, sh[0].l);
  EXPECT_THROW((void)pdd::shield_graded_decomposition(d2, {1.0}, pdd::sequential_executor{}, cap),
               pdd::decomposition_error);
}

} // namespace

} // namespace graded_shields_test
