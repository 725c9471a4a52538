// pdd::detail::off_centre, the refinement point of both kernels (kernels/detail/off_centre.hpp):
// on random triangles (fixed seed), where it is not the circumcentre it lies on the segment
// from the shortest edge's midpoint to the circumcentre, at h = 0.95 (|pq| / 2) cot(theta / 2)
// from the midpoint, inside the circumdisk, and the triangle it makes with the shortest edge
// meets the angle bound; where it is the circumcentre, the circumcentre was no further than h.
#include <pdd/core/triangle_measures.hpp>
#include <pdd/kernels/detail/off_centre.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace off_centre_test {
namespace {

using pdd::point;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;

point circumcentre(const point& a, const point& b, const point& c) {
  const K::Point_2 o =
      CGAL::circumcenter(K::Point_2(a.x, a.y), K::Point_2(b.x, b.y), K::Point_2(c.x, c.y));
  return {o.x(), o.y()};
}

double distance(const point& p, const point& q) {
  return std::hypot(p.x - q.x, p.y - q.y);
}

double min_angle_deg(const point& a, const point& b, const point& c) {
  const auto angles = pdd::detail::triangle_angles_deg(a, b, c);
  return std::min({angles[0], angles[1], angles[2]});
}

double shape_bound(double theta_deg) {
  const double s = std::sin(theta_deg * std::numbers::pi / 180.0);
  return s * s;
}

struct checked {
  int off = 0, circum = 0;
};

/// Checks off_centre on triangle (a, b, c) under the angle bound theta_deg (file comment).
void check_triangle(const point& a, const point& b, const point& c, double theta_deg,
                    checked& count) {
  const point cc = circumcentre(a, b, c);
  const point o = pdd::detail::off_centre(a, b, c, cc, shape_bound(theta_deg));
  const point* v[3] = {&a, &b, &c};
  int k = 0; // the shortest edge is v[k + 1] v[k + 2]
  for (int i = 1; i < 3; ++i)
    if (distance(*v[(i + 1) % 3], *v[(i + 2) % 3]) < distance(*v[(k + 1) % 3], *v[(k + 2) % 3]))
      k = i;
  const point &p = *v[(k + 1) % 3], &q = *v[(k + 2) % 3];
  const point m{0.5 * (p.x + q.x), 0.5 * (p.y + q.y)};
  const double h = 0.95 * 0.5 * distance(p, q) / std::tan(theta_deg * std::numbers::pi / 360.0);
  if (o.x == cc.x && o.y == cc.y) {
    ++count.circum;
    EXPECT_LE(distance(m, cc), h * (1 + 1e-9));
    return;
  }
  ++count.off;
  const double scale = distance(m, cc);
  EXPECT_GT(scale, h);
  EXPECT_NEAR(distance(m, o), h, 1e-9 * scale);
  // on the segment m -> cc: collinear and between
  const double cross = (o.x - m.x) * (cc.y - m.y) - (o.y - m.y) * (cc.x - m.x);
  EXPECT_NEAR(cross, 0.0, 1e-9 * scale * scale);
  EXPECT_NEAR(distance(m, o) + distance(o, cc), scale, 1e-9 * scale);
  EXPECT_LT(distance(o, cc), distance(cc, a)); // inside the circumdisk
  const double made = min_angle_deg(p, q, o);
  EXPECT_GT(made, theta_deg) << "the off-centre's triangle with the shortest edge is good";
  EXPECT_LT(made, theta_deg * 1.15) << "and not much better: the point is as far as it can be";
}

TEST(OffCentre, RandomTrianglesUnderSeveralBounds) {
  std::mt19937 random(20260);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  std::uniform_real_distribution<double> skinniness(-8.0, 0.0);
  for (const double theta : {20.0, 20.7, 28.0, 33.0}) {
    checked count;
    for (int n = 0; n < 2000; ++n) {
      const point a{coordinate(random), coordinate(random)};
      const point b{coordinate(random), coordinate(random)};
      // c near the line ab at a random relative height: from very skinny to fat
      const double t = coordinate(random), lift = std::pow(10.0, skinniness(random));
      const point c{a.x + t * (b.x - a.x) - lift * (b.y - a.y),
                    a.y + t * (b.y - a.y) + lift * (b.x - a.x)};
      if (min_angle_deg(a, b, c) <= 0.0) continue;
      check_triangle(a, b, c, theta, count);
    }
    EXPECT_GT(count.off, 500) << theta;    // skinny triangles get off-centres
    EXPECT_GT(count.circum, 100) << theta; // the others their circumcentres
  }
}

TEST(OffCentre, GoodTrianglesAndNoAngleBoundKeepTheCircumcentre) {
  const point a{0, 0}, b{1, 0}, c{0.5, std::sqrt(3.0) / 2};
  const point cc = circumcentre(a, b, c);
  const point o = pdd::detail::off_centre(a, b, c, cc, shape_bound(20.7));
  EXPECT_EQ(o.x, cc.x);
  EXPECT_EQ(o.y, cc.y);
  const point skinny{0.5, 1e-3};
  const point far = circumcentre(a, b, skinny);
  const point none = pdd::detail::off_centre(a, b, skinny, far, 0.0);
  EXPECT_EQ(none.x, far.x);
  EXPECT_EQ(none.y, far.y);
  const point taken = pdd::detail::off_centre(a, b, skinny, far, shape_bound(20.7));
  EXPECT_NE(taken.y, far.y);
}

} // namespace
} // namespace off_centre_test
