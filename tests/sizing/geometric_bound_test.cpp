// Tests of the per-subdomain numbers of Algorithm 8.3 (dissertation 8.2): relations 8.9-8.13
// and the R2 propagation (the heap against the text's O(N^2) sorted-list loop).
#include <pdd/errors.hpp>
#include <pdd/sizing/geometric_bound.hpp>
#include <pdd/sizing/piecewise_scaled.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <utility>
#include <vector>

namespace geometric_bound_test {
namespace {

using pairs = std::vector<std::pair<std::size_t, std::size_t>>;

TEST(GeometricBound, RelationsByHand) {
  // 8.9 (with its min): m_i = min((1/2) sqrt(m_f / sqrt2), lfs). m_f = 0.01:
  // (1/2) sqrt(0.01 / 1.41421356) = (1/2) 0.0840896415 = 0.0420448208.
  EXPECT_NEAR(pdd::geometric_edge_term(0.01, 1.0), 0.0420448208, 1e-10);
  EXPECT_DOUBLE_EQ(pdd::geometric_edge_term(0.01, 0.01), 0.01);
  // 8.11: no angle below 60 deg: e = m_i (a 90 deg corner is ignored)
  const std::vector<double> right{std::numbers::pi / 2};
  EXPECT_NEAR(pdd::geometric_edge_bound(0.01, 1.0, right), 0.0420448208, 1e-10);
  // 8.10 at theta = 30 deg, m_f = 0.01, lfs = 1: sin 30 = 0.5, sin 15 = 0.258819045,
  // cos 15 = 0.965925826. Shielded term: (1 + 0.51763809) sqrt(2 * 0.01 * 0.5) / sqrt3 =
  // 1.51763809 * 0.1 / 1.73205081 = 0.0876205; m_i / (cos 15 + sin 30) = 0.0420448208 /
  // 1.465925826 = 0.0286815. e = 0.0286815.
  const std::vector<double> thirty{std::numbers::pi / 6};
  EXPECT_NEAR(pdd::geometric_edge_bound(0.01, 1.0, thirty), 0.0286815, 1e-6);
  // a tiny m_f makes the shielded term the smaller: m_f = 1e-8, lfs = 1: m_i = (1/2)
  // sqrt(1e-8 / sqrt2) = 4.20448e-5, / 1.465925826 = 2.86815e-5; shielded: 1.51763809 *
  // sqrt(1e-8) / 1.73205081 = 8.76205e-5. So e = 2.86815e-5 still; at theta = 1 deg:
  // sin 1 = 0.0174524, sin 0.5 = 0.00872654, cos 0.5 = 0.999962: shielded = 1.01745 *
  // sqrt(2e-8 * 0.0174524) / 1.73205 = 1.01745 * 1.86828e-5 / 1.73205 = 1.09748e-5;
  // m_i / (0.999962 + 0.0174524) = 4.13256e-5. e = 1.09748e-5.
  const std::vector<double> one{std::numbers::pi / 180};
  EXPECT_NEAR(pdd::geometric_edge_bound(1e-8, 1.0, one) / 1.09748e-5, 1.0, 1e-4);
  // 8.13: g = 4 sqrt2 e^2; with e = m_i from the area term, g = m_f exactly (up to rounding)
  EXPECT_NEAR(pdd::geometric_area_bound(pdd::geometric_edge_term(0.01, 1.0)), 0.01, 1e-15);
  EXPECT_NEAR(pdd::geometric_area_bound(0.01), 5.656854249e-4, 1e-12);
  EXPECT_THROW(pdd::geometric_edge_bound(0.0, 1.0), pdd::sizing_error);
  EXPECT_THROW(pdd::geometric_edge_bound(1.0, 0.0), pdd::sizing_error);
}

TEST(GeometricBound, PropagationByHand) {
  // a path 0 - 1 - 2 - 3 and R2 = 1.5: g = (1, 100, 2, 100) -> (1, 1.5, 2, 3)
  std::vector<double> g{1.0, 100.0, 2.0, 100.0};
  const pairs p{{0, 1}, {2, 1}, {2, 3}};
  EXPECT_EQ(pdd::propagate_gradation(g, p, 1.5), 2u);
  EXPECT_EQ(g, (std::vector<double>{1.0, 1.5, 2.0, 3.0}));
  std::vector<double> bad{1.0, 0.0};
  EXPECT_THROW(pdd::propagate_gradation(bad, p, 1.5), pdd::sizing_error);
  std::vector<double> ok{1.0, 2.0};
  EXPECT_THROW(pdd::propagate_gradation(ok, pairs{{0, 5}}, 1.5), pdd::sizing_error);
  EXPECT_THROW(pdd::propagate_gradation(ok, pairs{{0, 1}}, 1.0), pdd::sizing_error);
}

// Algorithm 8.3 steps 2-11 as the text writes them (with its slip fixed: the list is sorted
// in increasing order): scan the sorted list; lower every later neighbour above R2 g_i and
// reposition it in the rest of the list. O(N^2).
std::vector<double> text_loop(std::vector<double> g, const pairs& p, double r2) {
  const std::size_t n = g.size();
  std::vector<std::vector<std::size_t>> adj(n);
  for (const auto& [a, b] : p) {
    adj[a].push_back(b);
    adj[b].push_back(a);
  }
  std::vector<std::size_t> list(n);
  for (std::size_t i = 0; i < n; ++i)
    list[i] = i;
  std::stable_sort(list.begin(), list.end(), [&](auto a, auto b) { return g[a] < g[b]; });
  for (std::size_t pos = 0; pos + 1 < n; ++pos) {
    const std::size_t i = list[pos];
    for (const std::size_t j : adj[i]) {
      const auto at = std::find(list.begin() + static_cast<std::ptrdiff_t>(pos) + 1, list.end(), j);
      if (at == list.end() || !(g[j] > r2 * g[i])) continue; // j settled earlier, or fine
      g[j] = r2 * g[i];
      list.erase(at);
      const auto to = std::upper_bound(list.begin() + static_cast<std::ptrdiff_t>(pos) + 1,
                                       list.end(), j, [&](auto a, auto b) { return g[a] < g[b]; });
      list.insert(to, j);
    }
  }
  return g;
}

TEST(GeometricBound, HeapEqualsTheTextsLoop) {
  std::mt19937_64 rng(1717);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::size_t lowered_total = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const std::size_t n = 2 + static_cast<std::size_t>(unit(rng) * 80);
    std::vector<double> g(n);
    for (double& v : g)
      v = std::pow(10.0, -8.0 * unit(rng)); // scales over 8 decades, like tiny features
    pairs p;
    for (std::size_t i = 1; i < n; ++i) // a random tree keeps it connected, then extra edges
      p.emplace_back(static_cast<std::size_t>(unit(rng) * i), i);
    for (std::size_t e = 0; e < n; ++e)
      p.emplace_back(static_cast<std::size_t>(unit(rng) * n),
                     static_cast<std::size_t>(unit(rng) * n));
    const double r2 = 1.0 + 1.9 * unit(rng) + 1e-3;
    const std::vector<double> expected = text_loop(g, p, r2);
    std::vector<double> heap = g;
    lowered_total += pdd::propagate_gradation(heap, p, r2);
    ASSERT_EQ(heap, expected) << "trial " << trial;
    for (const auto& [a, b] : p) // condition (iv)
      ASSERT_LE(heap[a], r2 * heap[b] * (1 + 1e-15));
  }
  EXPECT_GT(lowered_total, 1000u); // the instances did exercise the propagation
}

TEST(PiecewiseScaled, LocatesThePieceAndBounds) {
  // two unit squares side by side, each as two triangles; f uniform 2 (max_area 2), scales
  // 0.25 (left) and 0.5 (right)
  std::vector<pdd::point> v{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {2, 0}, {2, 1}};
  std::vector<std::array<pdd::index_t, 3>> t{{0, 1, 2}, {0, 2, 3}, {1, 4, 5}, {1, 5, 2}};
  const pdd::piecewise_scaled_sizing f({}, 2.0, v, t, {0, 0, 1, 1}, {0.25, 0.5},
                                       {{0.5, 0.5}, {1.0, 1.0}});
  EXPECT_DOUBLE_EQ(f.area_at({0.5, 0.4}), 0.5);
  EXPECT_DOUBLE_EQ(f.area_at({1.5, 0.4}), 1.0);
  EXPECT_DOUBLE_EQ(f.area_at({5.0, 5.0}), 0.5); // outside: the smallest scale
  EXPECT_DOUBLE_EQ(f.range({1.2, 0.1, 1.8, 0.9}).lo, 1.0);
  EXPECT_DOUBLE_EQ(f.range({0.2, 0.1, 1.8, 0.9}).lo, 0.5);
  EXPECT_DOUBLE_EQ(f.piece_bounds(1).lo, 1.0);
  EXPECT_THROW(pdd::piecewise_scaled_sizing({}, 2.0, v, t, {0, 0, 1, 2}, {0.25, 0.5},
                                            {{0.5, 0.5}, {1.0, 1.0}}),
               pdd::sizing_error);
  EXPECT_THROW(pdd::piecewise_scaled_sizing({}, 2.0, v, t, {0, 0, 1, 1}, {0.25, 0.0},
                                            {{0.5, 0.5}, {1.0, 1.0}}),
               pdd::sizing_error);
}

} // namespace

} // namespace geometric_bound_test
