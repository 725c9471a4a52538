// core/triangle_measures.hpp: the one-atan2 smallest angle agrees with the smallest of the three
// angles, on hand-made triangles and on random ones (fixed seed), thin and near-equilateral ones
// included (where the shortest edge is nearly tied).
#include <pdd/core/triangle_measures.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using pdd::point;
using pdd::detail::angle_at_deg;
using pdd::detail::smallest_angle_deg;
using pdd::detail::triangle_angles_deg;

namespace {
double smallest_of_three(const point& a, const point& b, const point& c) {
  const auto ang = triangle_angles_deg(a, b, c);
  return std::min({ang[0], ang[1], ang[2]});
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
  std::mt19937_64 rng(20261126);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_real_distribution<double> tiny(-1e-6, 1e-6);
  int exact = 0;
  for (int i = 0; i < 100000; ++i) {
    const point a{u(rng), u(rng)}, b{u(rng), u(rng)};
    // every fourth triangle nearly equilateral, every fourth nearly isosceles-thin
    point c{u(rng), u(rng)};
    if (i % 4 == 1)
      c = {(a.x + b.x) / 2 - (b.y - a.y) * std::sqrt(3.0) / 2 + tiny(rng),
           (a.y + b.y) / 2 + (b.x - a.x) * std::sqrt(3.0) / 2 + tiny(rng)};
    if (i % 4 == 2) c = {(a.x + b.x) / 2 - (b.y - a.y) * 1e3, (a.y + b.y) / 2 + (b.x - a.x) * 1e3};
    const double one = smallest_angle_deg(a, b, c), three = smallest_of_three(a, b, c);
    EXPECT_NEAR(one, three, 1e-9 * std::max(1.0, three)) << i;
    exact += one == three;
  }
  EXPECT_GT(exact, 99000); // the same corner, hence the same bits, but where edges nearly tie
}
