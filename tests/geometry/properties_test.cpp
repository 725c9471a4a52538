// Tests of pdd/geometry/properties.hpp: bounding box, domain-side angles, analyze(), and the
// properties of the shared test geometries.
#include "random_domains.hpp"
#include "test_support.hpp"

#include <pdd/geometry/properties.hpp>
#include <pdd/io/poly.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <string>
#include <vector>

namespace properties_test {
namespace {

using pdd::index_t;
using pdd::point;

std::vector<point> square(double x0, double y0, double s) {
  return {{x0, y0}, {x0 + s, y0}, {x0 + s, y0 + s}, {x0, y0 + s}};
}

/// A wedge with apex angle `deg` at vertex 0 (the apex), closed by an arc of 8 segments.
pdd::pslg wedge(double deg, bool clockwise) {
  std::vector<point> p{{0, 0}};
  const double a = deg * std::numbers::pi / 180;
  for (int i = 0; i <= 8; ++i)
    p.push_back({10 * std::cos(a * i / 8), 10 * std::sin(a * i / 8)});
  if (clockwise) std::reverse(p.begin() + 1, p.end());
  pdd::pslg g;
  g.add_loop(p);
  return g;
}

TEST(Properties, BoundingBox) {
  pdd::pslg g;
  g.add_loop(std::vector<point>{{-1, 2}, {3, -4}, {5, 6}});
  const auto b = pdd::bounding_box(g);
  EXPECT_EQ(b.xmin, -1);
  EXPECT_EQ(b.ymin, -4);
  EXPECT_EQ(b.xmax, 5);
  EXPECT_EQ(b.ymax, 6);
  EXPECT_EQ(b.width(), 6);
  EXPECT_EQ(b.height(), 10);
  EXPECT_GT(pdd::bounding_box(pdd::pslg{}).xmin, pdd::bounding_box(pdd::pslg{}).xmax);
}

TEST(Properties, WedgeAngleEitherOrientation) {
  for (double deg : {5.0, 17.5, 45.0, 60.0}) {
    for (bool cw : {false, true}) {
      index_t v = 99;
      EXPECT_NEAR(pdd::min_domain_angle_deg(wedge(deg, cw), &v), deg, 1e-10) << deg << cw;
      EXPECT_EQ(v, 0u);
    }
  }
}

TEST(Properties, HoleAnglesAreMeasuredOnTheDomainSide) {
  // a triangular hole with a 10 degree tip: the domain sees 350 degrees there; the smallest
  // domain angle is the square's 90, unless the hole's interior angles are reflex.
  pdd::pslg g;
  g.add_loop(square(0, 0, 10));
  const double t = std::tan(5 * std::numbers::pi / 180);
  g.add_loop(std::vector<point>{{2, 5}, {8, 5 - 6 * t}, {8, 5 + 6 * t}});
  g.holes.push_back({7, 5});
  index_t v = 0;
  EXPECT_DOUBLE_EQ(pdd::min_domain_angle_deg(g, &v), 90.0);
  EXPECT_EQ(v, 0u);
  // a square hole with a V notch cut from its left side: at the notch tip the hole's
  // interior angle is reflex and the domain sees the notch's 67.38 degrees
  pdd::pslg h;
  h.add_loop(square(-5, -5, 20));
  h.add_loop(std::vector<point>{{1, 1}, {3, 1}, {3, 3}, {1, 3}, {2.5, 2}});
  h.holes.push_back({2.8, 2});
  EXPECT_NEAR(pdd::min_domain_angle_deg(h, &v), 2 * std::atan(1 / 1.5) * 180 / std::numbers::pi,
              1e-12);
  EXPECT_EQ(v, 8u);
}

TEST(Properties, AnalyzeAgreesWithTheSeparateFunctions) {
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    const auto d = pdd::test::random_domain(seed);
    const auto p = pdd::analyze(d.g);
    EXPECT_EQ(p.area, pdd::domain_area(d.g));
    EXPECT_EQ(p.lfs_min, pdd::lfs_min(d.g));
    index_t v = 0;
    EXPECT_EQ(p.min_angle_deg, pdd::min_domain_angle_deg(d.g, &v));
    EXPECT_EQ(p.min_angle_vertex, v);
    const auto b = pdd::bounding_box(d.g);
    EXPECT_EQ(p.box.xmin, b.xmin);
    EXPECT_EQ(p.box.ymax, b.ymax);
    std::size_t even = 0;
    for (const auto& l : d.loops)
      even += l.depth % 2 == 0;
    EXPECT_EQ(p.num_loops, d.loops.size());
    EXPECT_EQ(p.num_outer_loops, even);
    EXPECT_EQ(p.num_holes, d.loops.size() - even);
    EXPECT_GT(p.min_angle_deg, 0);
    EXPECT_LT(p.min_angle_deg, 180);
  }
}

TEST(Properties, MinAngleMatchesPerVertexReference) {
  // reference: at each vertex, the angle between its two segments on the side where a point
  // just off the vertex along the bisector is inside the domain (checked by nesting depth)
  for (std::uint64_t seed = 1; seed <= 60; ++seed) {
    const auto d = pdd::test::random_domain(seed);
    const auto ls = pdd::find_loops(d.g);
    double ref = 360;
    for (const auto& l : ls.loops) {
      const std::size_t n = l.vertices.size();
      for (std::size_t i = 0; i < n; ++i) {
        const point a = d.g.vertices[l.vertices[(i + n - 1) % n]], v = d.g.vertices[l.vertices[i]],
                    b = d.g.vertices[l.vertices[(i + 1) % n]];
        const double ang =
            std::acos(std::clamp(((a.x - v.x) * (b.x - v.x) + (a.y - v.y) * (b.y - v.y)) /
                                     std::hypot(a.x - v.x, a.y - v.y) /
                                     std::hypot(b.x - v.x, b.y - v.y),
                                 -1.0, 1.0)) *
            180 / std::numbers::pi;
        // the loop's interior angle is convex iff the turn agrees with the orientation
        const double cross = (v.x - a.x) * (b.y - v.y) - (v.y - a.y) * (b.x - v.x);
        const double interior = (cross > 0) == l.counterclockwise ? ang : 360 - ang;
        ref = std::min(ref, l.bounds_domain_inside ? interior : 360 - interior);
      }
    }
    EXPECT_NEAR(pdd::min_domain_angle_deg(d.g), ref, 1e-9) << seed;
  }
}

TEST(Properties, SharedGeometries) {
  const auto files = pdd::test::shared_poly_files();
  if (files.empty()) GTEST_SKIP() << "no ../shared/data";
  // smallest domain-side angle (degrees) and loop counts from shared/data/README.md
  const std::map<std::string, std::pair<double, std::size_t>> expected{
      {"triangle_A.poly", {90.0, 1}},
      {"lake_superior.poly", {15.02, 6}},
      {"bahamas_islands.poly", {25.41, 276}},
      {"mesh2d_airfoil_3element.poly", {113.61, 3}},
      {"texas.poly", {7.29, 0}},
      {"guitar.poly", {45.0, 3}}};
  std::size_t analysed = 0, general = 0, expected_present = 0;
  for (const auto& f : files) {
    const std::string name = f.filename().string();
    const pdd::pslg g = pdd::read_poly(f);
    expected_present += expected.count(name);
    if (name == "triangle_face.poly" || name == "cgal_clusters.poly") {
      // not closed loops: Triangle's faces, the angles between segments, no lfs
      const auto p = pdd::analyze(g);
      EXPECT_FALSE(p.closed_loops) << name;
      EXPECT_GT(p.area, 0) << name;
      EXPECT_TRUE(std::isnan(p.lfs_min)) << name;
      EXPECT_EQ(p.num_loops, 0u) << name;
      if (name == "cgal_clusters.poly") {
        EXPECT_NEAR(p.min_angle_deg, 6.8, 0.05) << name;
      }
      ++general;
      continue;
    }
    const auto p = pdd::analyze(g);
    const auto b = pdd::bounding_box(g);
    EXPECT_GT(p.area, 0) << name;
    EXPECT_LE(p.area, b.width() * b.height()) << name;
    EXPECT_GT(p.lfs_min, 0) << name;
    EXPECT_EQ(p.num_outer_loops, 1u) << name;
    const auto it = expected.find(name);
    if (it == expected.end()) continue; // a new file: no reference values
    EXPECT_NEAR(p.min_angle_deg, it->second.first, 0.005) << name;
    EXPECT_EQ(p.num_holes, it->second.second) << name;
    EXPECT_EQ(p.num_holes, g.holes.size()) << name;
    ++analysed;
  }
  EXPECT_EQ(analysed, expected_present);
  EXPECT_LE(general, 2u);
}

} // namespace

} // namespace properties_test
