// pdd::sizing_range over a region (issue 36 item 2): a field is bounded over the domain itself,
// so one that is positive and finite on the domain is accepted whatever it does in its holes
// and outside (it is never even evaluated there), its bounds hold at every point of the domain,
// a field that is not positive somewhere in the domain is refused naming a point of the domain,
// and pdd::generate meshes a domain with such a field at one and several subdomains.
#include <pdd/errors.hpp>
#include <pdd/generate.hpp>
#include <pdd/geometry/domain_faces.hpp>
#include <pdd/mesh/verify.hpp>
#include <pdd/sizing/analytic.hpp>
#include <pdd/sizing/any_sizing.hpp>
#include <pdd/sizing/domain_region.hpp>
#include <pdd/sizing/min_sizing.hpp>
#include <pdd/sizing/sizing_range.hpp>
#include <pdd/sizing/uniform.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace region_range_test {
namespace {

using pdd::point;

std::vector<point> circle(point c, double r, int n, bool clockwise = false) {
  std::vector<point> p;
  for (int i = 0; i < n; ++i) {
    const double t = 2 * std::numbers::pi * (clockwise ? n - i : i) / n;
    p.push_back({c.x + r * std::cos(t), c.y + r * std::sin(t)});
  }
  return p;
}

/// A square [-1, 1]^2 with a circular hole of radius `hole` at the origin (n segments).
pdd::pslg square_with_hole(double hole, int n = 48) {
  pdd::pslg g;
  g.add_loop(std::vector<point>{{-1, -1}, {1, -1}, {1, 1}, {-1, 1}});
  g.add_loop(circle({0, 0}, hole, n, true));
  g.holes.push_back({0, 0});
  return g;
}

std::string sizing_error_of(const auto& f) {
  try {
    f();
  } catch (const pdd::sizing_error& e) {
    return e.what();
  }
  return "no sizing_error";
}

/// `count` points spread over the region (random barycentric points of its triangles, picked
/// by area), and every corner of it.
std::vector<point> points_in(const pdd::triangulated_region& r, std::size_t count,
                             std::mt19937& rng) {
  std::vector<double> area;
  for (const auto& t : r.triangles) {
    const point a = r.vertices[t[0]], b = r.vertices[t[1]], c = r.vertices[t[2]];
    area.push_back(std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)));
  }
  std::discrete_distribution<std::size_t> pick(area.begin(), area.end());
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<point> out(r.vertices);
  for (std::size_t k = 0; k < count; ++k) {
    const auto& t = r.triangles[pick(rng)];
    double s = u(rng), w = u(rng);
    if (s + w > 1) s = 1 - s, w = 1 - w;
    const point a = r.vertices[t[0]], b = r.vertices[t[1]], c = r.vertices[t[2]];
    out.push_back(
        {a.x + s * (b.x - a.x) + w * (c.x - a.x), a.y + s * (b.y - a.y) + w * (c.y - a.y)});
  }
  return out;
}

TEST(SizingRegionRange, AFieldUndefinedOutsideTheDomainIsNeverEvaluatedThere) {
  pdd::pslg disk;
  disk.add_loop(circle({0, 0}, 1.0, 64));
  const pdd::triangulated_region region = pdd::domain_region(disk);
  // NaN outside the unit circle (which the 64-gon lies in); throws if asked there at all
  const pdd::analytic_sizing f{[](const point& p) {
    const double r2 = p.x * p.x + p.y * p.y;
    if (r2 > 1.0 + 1e-12) throw std::logic_error("evaluated outside the domain");
    return 1e-2 * (0.5 + std::sqrt(1.0 - std::min(r2, 1.0)));
  }};
  const pdd::sizing_bounds b = pdd::sizing_range(f, region.view());
  EXPECT_GT(b.lo, 0.0);
  EXPECT_LE(b.lo, 1e-2 * 0.5 + 1e-2 * std::sqrt(1 - std::pow(std::cos(std::numbers::pi / 64), 2)));
  EXPECT_GE(b.hi, 1.5e-2);
  // over the box the field is asked outside the circle: refused
  EXPECT_THROW((void)pdd::sizing_range(f, region.view().box()), std::logic_error);
}

TEST(SizingRegionRange, AFieldThatVanishesInAHoleIsAcceptedAndBounded) {
  const pdd::pslg g = square_with_hole(0.3);
  const pdd::triangulated_region region = pdd::domain_region(g);
  // zero at r = 0.2, inside the hole; >= 1e-3 * 0.296 on the domain (the 48-gon's inradius)
  const pdd::analytic_sizing f{[](const point& p) { return 1e-3 * (std::hypot(p.x, p.y) - 0.2); }};
  const pdd::sizing_bounds b = pdd::sizing_range(f, region.view());
  const double inradius = 0.3 * std::cos(std::numbers::pi / 48);
  EXPECT_GT(b.lo, 0.5e-3 * (inradius - 0.2));
  EXPECT_LE(b.lo, 1e-3 * (inradius - 0.2));
  EXPECT_GE(b.hi, 1e-3 * (std::sqrt(2.0) - 0.2));
  EXPECT_NE(sizing_error_of([&] { (void)pdd::sizing_range(f, region.view().box()); }),
            "no sizing_error"); // the box holds the hole
  // through any_sizing and min_sizing alike
  const pdd::any_sizing held(f);
  EXPECT_EQ(pdd::sizing_range(held, region.view()).lo, b.lo);
  const pdd::min_sizing both(pdd::uniform_sizing{1.0}, held);
  EXPECT_EQ(pdd::sizing_range(both, region.view()).lo, b.lo);
}

TEST(SizingRegionRange, AFieldNotPositiveInTheDomainIsRefusedNamingAPointOfIt) {
  const pdd::pslg g = square_with_hole(0.3);
  const pdd::triangulated_region region = pdd::domain_region(g);
  const pdd::domain_faces faces(g);
  const pdd::analytic_sizing f{[](const point& p) { return p.x - 0.5; }}; // <= 0 left of 0.5
  const std::string msg = sizing_error_of([&] { (void)pdd::sizing_range(f, region.view()); });
  ASSERT_NE(msg.find("a point of the domain"), std::string::npos) << msg;
  point named{};
  ASSERT_EQ(std::sscanf(msg.c_str() + msg.find(" at (") + 5, "%lf, %lf", &named.x, &named.y), 2);
  EXPECT_LE(named.x, 0.5);
  EXPECT_NE(faces.locate(named).where, pdd::face_location::kind::outside) << msg;
}

// A degenerate triangle of a region (three points on a line) adds only the points of its line:
// the grid nodes around it are not taken for points of the region.
TEST(SizingRegionRange, ADegenerateTriangleAddsOnlyItsLine) {
  const std::vector<point> v{{0, 0}, {1, 0}, {0, 1}, {2, 2}, {3, 2.5}, {4, 3}};
  const std::vector<std::array<pdd::index_t, 3>> t{{0, 1, 2}, {3, 4, 5}};
  // defined on the triangle and on the line y = 1 + x / 2 through the degenerate one; throws
  // anywhere else
  const pdd::analytic_sizing f{[](const point& p) {
    const bool in_triangle = p.x >= -1e-12 && p.y >= -1e-12 && p.x + p.y <= 1 + 1e-12;
    if (!in_triangle && std::abs(p.y - (1 + p.x / 2)) > 1e-9)
      throw std::logic_error("evaluated off the region");
    return 1.0 + p.x;
  }};
  const pdd::sizing_bounds b = pdd::sizing_range(f, pdd::sizing_region{v, t});
  EXPECT_GT(b.lo, 0.0);
  EXPECT_LE(b.lo, 1.0);
  EXPECT_GE(b.hi, 5.0); // x = 4 at the line's end
}

// Random domains (a star-shaped outer loop, a polygonal hole) and fields positive on the domain
// but negative inside the hole: F = a + s (|p - h|^2 - rho^2), rho the hole's inradius, so
// F >= a on the domain and F = a - s rho^2 < 0 at the hole's centre. A quadratic: the grid
// rule's curvature margin is exact, so lo must bound every point of the domain, and lo is within
// the margin of the true minimum a.
TEST(SizingRegionRange, BoundsHoldAtEveryPointOfRandomDomains) {
  std::mt19937 rng(36);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int round = 0; round < 40; ++round) {
    SCOPED_TRACE("round " + std::to_string(round));
    pdd::pslg g;
    std::vector<point> outer;
    for (int i = 0; i < 24; ++i) {
      const double t = 2 * std::numbers::pi * i / 24, r = 1.0 + 0.6 * u(rng);
      outer.push_back({r * std::cos(t), r * std::sin(t)});
    }
    g.add_loop(outer);
    const point h{0.3 * (u(rng) - 0.5), 0.3 * (u(rng) - 0.5)};
    const double hole = 0.2 + 0.4 * u(rng);
    const int sides = 5 + static_cast<int>(20 * u(rng));
    g.add_loop(circle(h, hole, sides, true));
    g.holes.push_back(h);
    const double rho = hole * std::cos(std::numbers::pi / sides);
    const double a = 1e-4 * (1 + 9 * u(rng)), s = (1 + 4 * u(rng)) * a / (rho * rho);
    const pdd::analytic_sizing f{[=](const point& p) {
      const double dx = p.x - h.x, dy = p.y - h.y;
      return a + s * (dx * dx + dy * dy - rho * rho);
    }};
    const pdd::triangulated_region region = pdd::domain_region(g);
    const pdd::sizing_bounds b = pdd::sizing_range(f, region.view());
    double lo = std::numeric_limits<double>::infinity(), hi = 0;
    for (const point& p : points_in(region, 4000, rng)) {
      lo = std::min(lo, f.area_at(p));
      hi = std::max(hi, f.area_at(p));
    }
    ASSERT_GT(lo, 0.0);
    EXPECT_LE(b.lo, lo);
    EXPECT_GE(b.hi, hi);
    EXPECT_GT(b.lo, 0.8 * a); // the margin s h^2 of 64 cells: a few percent of a
  }
}

// The case, scaled: a square with a hole and a distance-graded field that is zero
// inside the hole. pdd::generate meshed nothing before ("cannot be bounded away from 0"); now
// the whole-domain kernel and the graded path mesh it, and the mesh honours the field.
TEST(SizingRegionRange, GenerateMeshesWithAFieldThatVanishesInAHole) {
  const pdd::pslg g = square_with_hole(0.3);
  const pdd::analytic_sizing f{[](const point& p) {
    const double t = 1 + 4 * (std::hypot(p.x, p.y) - 0.3) / 0.7; // zero at r = 0.125
    return 4e-4 * t * t;
  }};
  for (const std::size_t n : {1u, 4u}) {
    SCOPED_TRACE("N " + std::to_string(n));
    pdd::generate_options o;
    o.sizing = f;
    o.subdomains = n;
    const pdd::generate_result r = pdd::generate(g, o);
    EXPECT_GE(r.statistics.subdomains, n);
    const pdd::verification_report rep =
        pdd::verify(r.mesh, g, pdd::verify_options{.criteria = o.criteria}, o.sizing);
    EXPECT_TRUE(rep.ok()) << (rep.messages.empty() ? "" : rep.messages.front());
    EXPECT_EQ(rep.area_violations, 0u);
  }
}

} // namespace
} // namespace region_range_test
