// Tests of Algorithm 8.3 on a decomposition (pdd::geometric_sizing, dissertation 8.2) and of
// the loop of decomposition and sizing (pdd::geometric_decompose).
#include "hand_decompositions.hpp"

#include <pdd/decoupling/geometric_decompose.hpp>
#include <pdd/decoupling/geometric_sizing.hpp>
#include <pdd/madd/decompose.hpp>
#include <pdd/parallel/sequential_executor.hpp>
#include <pdd/parallel/tbb_executor.hpp>
#include <pdd/sizing/analytic.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

namespace geometric_sizing_test {
namespace {

using pdd::point;

// Three unit squares [0,3] x [0,1] (grid_case(3, 1)); subdomain 0 gets a tiny feature: a
// vertex at (0.01, 0) on its bottom edge, 0.01 from the left side.
pdd::test::hand_case three_squares_with_a_tiny_feature() {
  pdd::test::hand_case c = pdd::test::grid_case(3, 1, 3.0, 1.0);
  pdd::decomposition& d = c.parts;
  const auto v = static_cast<pdd::index_t>(d.vertices.size());
  d.vertices.push_back({0.01, 0.0});
  d.vertex_markers.push_back(1);
  pdd::subdomain& s0 = d.subdomains[0];
  s0.loops[0].insert(s0.loops[0].begin() + 1, v);
  s0.tags[0].insert(s0.tags[0].begin() + 1, s0.tags[0][0]); // both halves on segment 0
  c.domain = pdd::pslg{};
  c.domain.add_loop(std::vector<point>{{0, 0}, {0.01, 0}, {3, 0}, {3, 1}, {0, 1}}, 0);
  return c;
}

TEST(GeometricSizing, ThreeSubdomainsByHand) {
  const auto c = three_squares_with_a_tiny_feature();
  // f: the uniform bound A = 0.001 (no field). By hand, R2 = 1.5:
  //  m_f(D_i) = 0.001 for all; the area term of 8.9: (1/2) sqrt(0.001 / sqrt2) = 0.0132957.
  //  lfs_min: D_0 0.01 (the vertex (0.01, 0) to the left side), D_1 = D_2 = 1 (unit squares).
  //  e_0 = min(0.0132957, 0.01) = 0.01 (corners 90 and 180 deg: no small angle, 8.11);
  //  e_1 = e_2 = 0.0132957.
  //  g_0 = 4 sqrt2 0.01^2 = 5.656854e-4; g_1 = g_2 = 4 sqrt2 0.0132957^2 = 0.001 (= m_f).
  //  R2 propagation: g_1 = min(0.001, 1.5 * 5.656854e-4 = 8.485281e-4) = 8.485281e-4;
  //  g_2 = min(0.001, 1.5 * 8.485281e-4 = 1.272792e-3) = 0.001 (unchanged).
  //  F = f g_i / m_f: 5.656854e-4, 8.485281e-4, 0.001 on D_0, D_1, D_2.
  //  Expected triangles under f: 1 / (0.656 * 0.001) = 1524.39 per square; under F:
  //  1524.39 (1 / 0.5656854 + 1 / 0.8485281 + 1) = 1524.39 * 3.946278 = 6015.66;
  //  over-refinement 3.946278 / 3 - 1 = 0.315426.
  const auto r = pdd::geometric_sizing(c.parts, {}, 0.001, 1.5);
  ASSERT_EQ(r.g.size(), 3u);
  EXPECT_NEAR(r.lfs[0], 0.01, 1e-15);
  EXPECT_NEAR(r.lfs[1], 1.0, 1e-15);
  EXPECT_NEAR(r.edge_bound[0], 0.01, 1e-15);
  EXPECT_NEAR(r.edge_bound[1], 0.0132957, 1e-7);
  EXPECT_NEAR(r.g[0], 5.656854e-4, 1e-10);
  EXPECT_NEAR(r.g[1], 8.485281e-4, 1e-10);
  EXPECT_NEAR(r.g[2], 0.001, 1e-15);
  EXPECT_EQ(r.lowered, 1u);
  const auto& F = *r.field;
  EXPECT_NEAR(F.area_at({0.5, 0.5}), 5.656854e-4, 1e-10);
  EXPECT_NEAR(F.area_at({1.5, 0.5}), 8.485281e-4, 1e-10);
  EXPECT_NEAR(F.area_at({2.5, 0.5}), 0.001, 1e-15);
  EXPECT_NEAR(F.piece_bounds(1).lo, 8.485281e-4, 1e-10);
  EXPECT_NEAR(F.range({0.2, 0.2, 2.8, 0.8}).lo, 5.656854e-4, 1e-10);
  EXPECT_NEAR(r.expected_triangles_F(), 6015.66, 0.05);
  EXPECT_NEAR(r.over_refinement(), 0.315426, 1e-5);
  // Proposition 25: (i) F <= f, (ii) m_F <= 4 sqrt2 e^2, (iv) m_F(D_i) <= R2 m_F(D_j)
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_LE(r.g[i], 0.001);
    EXPECT_LE(r.g[i], 4 * std::numbers::sqrt2 * r.edge_bound[i] * r.edge_bound[i] * (1 + 1e-15));
  }
  for (const auto& ic : c.parts.interfaces)
    EXPECT_LE(r.g[ic.a], 1.5 * r.g[ic.b] * (1 + 1e-15));
  // the same numbers on TBB's executor
  const auto t = pdd::geometric_sizing(c.parts, {}, 0.001, 1.5, pdd::tbb_executor{2});
  EXPECT_EQ(t.g, r.g);
}

TEST(GeometricSizing, NoBoundIsRefused) {
  const auto c = three_squares_with_a_tiny_feature();
  EXPECT_THROW(pdd::geometric_sizing(c.parts, {}, std::numeric_limits<double>::infinity(), 1.5),
               pdd::sizing_error);
}

// A square with a 1e-4 notch on its bottom side: the loop must grade the decomposition towards
// it and bring the over-refinement down from N-way MADD's.
TEST(GeometricDecompose, GradesTowardsATinyFeature) {
  pdd::pslg g;
  g.add_loop(
      std::vector<point>{
          {0, 0}, {0.5, 0}, {0.5, 1e-4}, {0.5001, 1e-4}, {0.5001, 0}, {1, 0}, {1, 1}, {0, 1}},
      0);
  const double a = 1e-4;
  pdd::madd_options mo;
  mo.subdomains = 16;
  const pdd::decomposition initial = pdd::decompose(g, mo);
  pdd::gradation_options go;
  go.min_subdomains = 16;
  const auto r = pdd::geometric_decompose(g, initial, {}, a, go, mo, {.max_subdomains = 2000});
  ASSERT_GE(r.rounds.size(), 2u);
  const double first = r.rounds.front().over_refinement;
  const double best = r.rounds[r.chosen].over_refinement;
  EXPECT_GT(first, 1.0); // N-way MADD: the notch's subdomain and its neighbours shrink
  EXPECT_LT(best, 0.05);
  EXPECT_EQ(r.parts.subdomains.size(), r.rounds[r.chosen].subdomains);
  EXPECT_EQ(r.sizing.g.size(), r.parts.subdomains.size());
  for (const auto& ic : r.parts.interfaces)
    EXPECT_LE(r.sizing.g[ic.a], go.r2 * r.sizing.g[ic.b] * (1 + 1e-15));
  for (const auto& round : r.rounds)
    std::printf(
        "round: %zu subdomains, %zu features, slope %g, over-refinement %.4f, expected %.0f%s\n",
        round.subdomains, round.features, round.slope, round.over_refinement,
        round.expected_triangles, round.capped ? " (capped)" : "");
}

// feature_driven_sizing measures only the features that can beat the minimum so far (a slab
// in x and a squared comparison): the result must be the plain minimum over every feature.
// Random features (clustered, so that many share a slab), slopes from 0 to 1, a base field
// that varies, queries near and far from the features; 200 seeds.
TEST(FeatureDrivenSizing, IsThePlainMinimumOverEveryFeature) {
  for (unsigned seed = 0; seed < 200; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const std::size_t n = 1 + seed % 97;
    const double slope = (seed % 5 == 0) ? 0.0 : unit(rng);
    const double max_area = (seed % 3 == 0) ? std::numeric_limits<double>::infinity() : 1e-2;
    std::vector<point> at;
    std::vector<double> half_gap;
    for (std::size_t i = 0; i < n; ++i) {
      const double cx = (i % 4) * 0.25;
      at.push_back({cx + 1e-3 * unit(rng), unit(rng)});
      half_gap.push_back(1e-4 * (1.0 + 50.0 * unit(rng)));
    }
    const pdd::any_sizing base{
        pdd::analytic_sizing{[](const point& p) { return 1e-3 * (1.0 + p.x * p.x + 2.0 * p.y); }}};
    const pdd::feature_driven_sizing field(base, max_area, at, half_gap, slope);
    for (int q = 0; q < 300; ++q) {
      const point p{-0.5 + 2.0 * unit(rng), -0.5 + 2.0 * unit(rng)};
      double expected = std::min(max_area, base.area_at(p));
      for (std::size_t i = 0; i < n; ++i) {
        const double dx = p.x - at[i].x;
        const double dy = p.y - at[i].y;
        const double e = half_gap[i] + slope * std::sqrt(dx * dx + dy * dy);
        expected = std::min(expected, 4.0 * std::numbers::sqrt2 * e * e);
      }
      ASSERT_EQ(field.area_at(p), expected) << "seed " << seed << " query " << q;
    }
  }
}

} // namespace

} // namespace geometric_sizing_test
