// core/triangle_measures.hpp: the one-atan2 smallest angle agrees with the smallest of the three
// angles, and the two-atan2 triangle_angles_deg with three angle_at_deg, on hand-made triangles
// and on random ones (fixed seed), thin and near-equilateral ones included (where the shortest
// edge is nearly tied).
#include <pdd/core/triangle_measures.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

namespace triangle_measures_test {
using pdd::point;
using pdd::detail::angle_at_deg;
using pdd::detail::smallest_angle_deg;
using pdd::detail::triangle_angles_deg;

namespace {
std::array<double, 3> three_atan2(const point& a, const point& b, const point& c) {
  return {angle_at_deg(a, b, c), angle_at_deg(b, c, a), angle_at_deg(c, a, b)};
}
double smallest_of_three(const point& a, const point& b, const point& c) {
  const auto ang = three_atan2(a, b, c);
  return std::min({ang[0], ang[1], ang[2]});
}
/// Random triangles: every fourth nearly equilateral, every fourth nearly isosceles-thin.
std::vector<std::array<point, 3>> random_triangles(std::size_t n) {
  std::mt19937_64 rng(20261126);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_real_distribution<double> tiny(-1e-6, 1e-6);
  std::vector<std::array<point, 3>> out;
  for (std::size_t i = 0; i < n; ++i) {
    const point a{u(rng), u(rng)}, b{u(rng), u(rng)};
    point c{u(rng), u(rng)};
    if (i % 4 == 1)
      c = {(a.x + b.x) / 2 - (b.y - a.y) * std::sqrt(3.0) / 2 + tiny(rng),
           (a.y + b.y) / 2 + (b.x - a.x) * std::sqrt(3.0) / 2 + tiny(rng)};
    if (i % 4 == 2) c = {(a.x + b.x) / 2 - (b.y - a.y) * 1e3, (a.y + b.y) / 2 + (b.x - a.x) * 1e3};
    out.push_back({a, b, c});
  }
  return out;
}
} // namespace

TEST(TriangleMeasures, SmallestAngleOfHandMadeTriangles) {
  EXPECT_NEAR(smallest_angle_deg({0, 0}, {1, 0}, {0, 1}), 45.0, 1e-12);
  EXPECT_NEAR(smallest_angle_deg({0, 0}, {1, 0}, {0.5, std::sqrt(3.0) / 2}), 60.0, 1e-12);
  // 30-60-90 with the short leg in every position
  const point p{0, 0}, q{std::sqrt(3.0), 0}, r{0, 1};
  for (const auto& t : {std::array{p, q, r}, std::array{q, r, p}, std::array{r, p, q}})
    EXPECT_NEAR(smallest_angle_deg(t[0], t[1], t[2]), 30.0, 1e-12);
  EXPECT_NEAR(angle_at_deg({0, 0}, {1, 0}, {-1, 1e-9}), 180.0, 1e-6);
}

TEST(TriangleMeasures, SmallestAngleMatchesTheSmallestOfThreeOnRandomTriangles) {
  int exact = 0, i = 0;
  for (const auto& [a, b, c] : random_triangles(100000)) {
    const double one = smallest_angle_deg(a, b, c), three = smallest_of_three(a, b, c);
    EXPECT_NEAR(one, three, 1e-9 * std::max(1.0, three)) << i++;
    exact += one == three;
  }
  EXPECT_GT(exact, 99000); // the same corner, hence the same bits, but where edges nearly tie
}

TEST(TriangleMeasures, AnglesMatchThreeAtan2AndSumTo180) {
  const auto right = triangle_angles_deg({0, 0}, {std::sqrt(3.0), 0}, {0, 1});
  EXPECT_NEAR(right[0], 90.0, 1e-12);
  EXPECT_NEAR(right[1], 30.0, 1e-12);
  EXPECT_NEAR(right[2], 60.0, 1e-12);
  const auto flat = triangle_angles_deg({0, 0}, {1, 0}, {2, 0}); // degenerate: 0, 180, 0
  EXPECT_EQ(flat[1], 180.0);
  EXPECT_EQ(flat[0] + flat[2], 0.0);
  int i = 0;
  for (const auto& [a, b, c] : random_triangles(100000)) {
    const auto two = triangle_angles_deg(a, b, c), three = three_atan2(a, b, c);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(two[k], three[k], 1e-9) << i << " corner " << k;
    EXPECT_NEAR(two[0] + two[1] + two[2], 180.0, 1e-12) << i;
    EXPECT_EQ(std::min({two[0], two[1], two[2]}), smallest_angle_deg(a, b, c)) << i;
    ++i;
  }
}

// degree_bin against its definition written out: the largest k in 1..179 with cos(k deg) >=
// c (0 when none, and for NaN), by a linear scan; at every bin boundary and its neighbouring
// doubles, near +-1 (the narrowest degrees in cosine), outside [-1, 1], and at random.
std::size_t degree_bin_by_definition(double c) {
  if (std::isnan(c)) return 0;
  static const std::vector<double> cosines = [] {
    std::vector<double> t;
    for (int i = 0; i <= 180; ++i)
      t.push_back(std::cos(static_cast<double>(i) * std::numbers::pi / 180.0));
    return t;
  }();
  std::size_t k = 0;
  for (std::size_t i = 1; i <= 179; ++i)
    if (cosines[i] >= c) k = i;
  return k;
}

TEST(TriangleMeasures, DegreeBinIsTheDefinition) {
  std::vector<double> values{std::nan(""),
                             std::numeric_limits<double>::infinity(),
                             -std::numeric_limits<double>::infinity(),
                             1.0,
                             -1.0,
                             0.0,
                             1.5,
                             -1.5};
  for (int k = 0; k <= 180; ++k) {
    const double b = std::cos(k * std::numbers::pi / 180.0);
    double lo = b, hi = b;
    for (int step = 0; step < 4; ++step) {
      values.push_back(lo);
      values.push_back(hi);
      lo = std::nextafter(lo, -2.0);
      hi = std::nextafter(hi, 2.0);
    }
  }
  std::mt19937_64 rng(180);
  std::uniform_real_distribution<double> any(-1.0, 1.0), near(0.0, 1e-3);
  for (int i = 0; i < 200000; ++i) {
    values.push_back(any(rng));
    values.push_back(1.0 - near(rng));
    values.push_back(-1.0 + near(rng));
  }
  for (const double c : values)
    ASSERT_EQ(pdd::detail::degree_bin(c), degree_bin_by_definition(c)) << std::hexfloat << c;
}

} // namespace triangle_measures_test
