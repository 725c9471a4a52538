// Tests of pdd::compute_statistics and pdd::verify: values on hand-made meshes, thread-count
// independence, and verifier checks that must fail on broken meshes.
#include "test_domains.hpp"
#include "test_support.hpp"

#include <pdd/core/kernel.hpp>
#include <pdd/geometry/model_domains.hpp>
#include <pdd/kernels/cgal/mesher.hpp>
#include <pdd/mesh/quality.hpp>
#include <pdd/mesh/verify.hpp>
#include <pdd/sizing/analytic.hpp>

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <cstring>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

namespace verify_test {
namespace {

using pdd::index_t;
using pdd::point;

pdd::triangle_mesh mesh_of(const pdd::pslg& d, double max_area) {
  pdd::mesh_criteria c;
  c.max_area = max_area;
  return pdd::cgal::mesher{}.mesh(d, c, pdd::uniform_sizing{}).mesh;
}

pdd::verify_options options(double max_area) {
  pdd::verify_options o;
  o.criteria.max_area = max_area;
  return o;
}

std::string describe(const pdd::verification_report& r) {
  std::string s;
  for (const auto& m : r.messages)
    s += m + "\n";
  return s;
}

bool stats_equal(const pdd::mesh_statistics& a, const pdd::mesh_statistics& b) {
  return a.triangles == b.triangles && a.vertices == b.vertices &&
         std::memcmp(&a.min_angle_deg, &b.min_angle_deg, sizeof(double)) == 0 &&
         std::memcmp(&a.max_angle_deg, &b.max_angle_deg, sizeof(double)) == 0 &&
         std::memcmp(&a.max_ratio, &b.max_ratio, sizeof(double)) == 0 &&
         std::memcmp(&a.max_area, &b.max_area, sizeof(double)) == 0 &&
         std::memcmp(&a.max_area_ratio, &b.max_area_ratio, sizeof(double)) == 0 &&
         std::memcmp(&a.area, &b.area, sizeof(double)) == 0 &&
         a.angle_histogram == b.angle_histogram;
}

/// The interior edges (u, v) of a mesh with the two triangles (left, right) using them.
std::vector<std::array<index_t, 4>> interior_edges(const pdd::triangle_mesh& m) {
  std::map<std::pair<index_t, index_t>, std::vector<index_t>> uses;
  for (index_t t = 0; t < m.triangles.size(); ++t)
    for (std::size_t i = 0; i < 3; ++i)
      uses[std::minmax(m.triangles[t][i], m.triangles[t][(i + 1) % 3])].push_back(t);
  std::vector<std::array<index_t, 4>> out;
  for (const auto& [e, ts] : uses)
    if (ts.size() == 2) out.push_back({e.first, e.second, ts[0], ts[1]});
  return out;
}

index_t apex(const std::array<index_t, 3>& t, index_t u, index_t v) {
  for (const index_t w : t)
    if (w != u && w != v) return w;
  return t[0];
}

} // namespace

TEST(Statistics, EquilateralAndRightTriangles) {
  pdd::triangle_mesh m;
  const double h = std::sqrt(3.0) / 2;
  m.vertices = {{0, 0}, {1, 0}, {0.5, h}, {0, -1}};
  m.vertex_markers.assign(4, 0);
  m.triangles = {{0, 1, 2}, {0, 3, 1}};
  m.triangle_markers = {0, 0};
  const auto s = pdd::compute_statistics(m);
  EXPECT_EQ(s.triangles, 2u);
  EXPECT_EQ(s.vertices, 4u);
  EXPECT_NEAR(s.min_angle_deg, 45, 1e-9);
  EXPECT_NEAR(s.max_angle_deg, 90, 1e-9);
  EXPECT_NEAR(s.max_ratio, 1 / std::sqrt(2.0), 1e-12); // right isosceles: R = sqrt2/2, l = 1
  EXPECT_NEAR(s.max_area, 0.5, 1e-15);
  EXPECT_NEAR(s.area, 0.5 + h / 2, 1e-15);
  EXPECT_EQ(s.max_area_ratio, 0.0);
  std::size_t total = 0;
  for (const auto c : s.angle_histogram)
    total += c;
  EXPECT_EQ(total, 6u);
  EXPECT_EQ(s.angle_histogram[59] + s.angle_histogram[60], 3u); // 60 deg up to rounding
  EXPECT_EQ(s.angle_histogram[44] + s.angle_histogram[45], 2u);
  EXPECT_EQ(s.angle_histogram[89] + s.angle_histogram[90], 1u);
  const auto sz = pdd::compute_statistics(m, pdd::uniform_sizing{0.25});
  EXPECT_NEAR(sz.max_area_ratio, 2.0, 1e-14);
  const auto empty = pdd::compute_statistics(pdd::triangle_mesh{});
  EXPECT_EQ(empty.triangles, 0u);
  EXPECT_EQ(empty.min_angle_deg, 0.0);
}

TEST(Statistics, SameForEveryThreadCount) {
  const auto m = mesh_of(pdd::pipe_domain(192, 24), 2e-4);
  ASSERT_GT(m.triangles.size(), 20000u);
  const pdd::analytic_sizing s{[](point p) { return 1e-4 + p.x * p.x; }};
  pdd::mesh_statistics one, four;
  tbb::task_arena(1).execute([&] { one = pdd::compute_statistics(m, s); });
  tbb::task_arena(4).execute([&] { four = pdd::compute_statistics(m, s); });
  EXPECT_TRUE(stats_equal(one, four));
  EXPECT_GT(one.max_area_ratio, 0.0);
  EXPECT_NEAR(one.area, pdd::domain_area(pdd::pipe_domain(192, 24)), 1e-9);
}

TEST(Verify, AcceptsKernelMeshes) {
  for (const auto& d : {pdd::test::square_with_hole(), pdd::test::two_holes(), pdd::key_domain(),
                        pdd::test::random_domain_60(3)}) {
    const auto m = mesh_of(d, 0.004);
    const auto r = pdd::verify(m, d, options(0.004));
    EXPECT_TRUE(r.ok()) << describe(r);
    EXPECT_TRUE(r.area_ok);
    EXPECT_NEAR(r.area_mesh, r.area_domain, 1e-9 * r.area_domain);
    EXPECT_TRUE(r.messages.empty());
  }
}

TEST(Verify, AcceptsSplitSlantedSegments) {
  // Slanted segments split many times: the Steiner points are rounded midpoints, generally
  // not exactly on the segment, and must still be accepted as a chain.
  pdd::pslg d;
  d.add_loop(std::vector<point>{{0.1, 0.3}, {2.7, 0.9}, {1.9, 2.3}, {0.3, 1.7}}, 1);
  const auto m = mesh_of(d, 1e-4);
  const auto r = pdd::verify(m, d, options(1e-4));
  EXPECT_TRUE(r.ok()) << describe(r);
  EXPECT_GT(m.vertices.size(), 1000u);
}

TEST(Verify, SameReportForEveryThreadCount) {
  const auto d = pdd::key_domain();
  auto m = mesh_of(d, 0.001);
  m.triangles.erase(m.triangles.begin() + 10);
  m.triangle_markers.pop_back();
  pdd::verification_report one, four;
  tbb::task_arena(1).execute([&] { one = pdd::verify(m, d, options(0.0005)); });
  tbb::task_arena(4).execute([&] { four = pdd::verify(m, d, options(0.0005)); });
  EXPECT_EQ(one.messages, four.messages);
  EXPECT_EQ(one.area_violations, four.area_violations);
  EXPECT_EQ(std::memcmp(&one.area_mesh, &four.area_mesh, sizeof(double)), 0);
}

TEST(Verify, DetectsAFlippedEdge) {
  const auto d = pdd::test::square_with_hole();
  auto m = mesh_of(d, 0.01);
  using K = pdd::epick;
  const auto P = [&](index_t v) { return K::Point_2(m.vertices[v].x, m.vertices[v].y); };
  bool flipped = false;
  for (const auto& [u, v, t0, t1] : interior_edges(m)) {
    const index_t a = apex(m.triangles[t0], u, v), b = apex(m.triangles[t1], u, v);
    // Flippable: the quadrilateral u a v b is strictly convex, and not cocircular.
    if (CGAL::orientation(P(a), P(b), P(u)) == CGAL::orientation(P(a), P(b), P(v)) ||
        CGAL::orientation(P(a), P(b), P(u)) == CGAL::COLLINEAR ||
        CGAL::orientation(P(a), P(b), P(v)) == CGAL::COLLINEAR ||
        CGAL::side_of_bounded_circle(P(u), P(v), P(a), P(b)) == CGAL::ON_BOUNDARY)
      continue;
    // New triangles (a, b, x), oriented counter-clockwise.
    const auto ccw = [&](index_t x, index_t y, index_t z) {
      return CGAL::orientation(P(x), P(y), P(z)) == CGAL::LEFT_TURN
                 ? std::array<index_t, 3>{x, y, z}
                 : std::array<index_t, 3>{x, z, y};
    };
    m.triangles[t0] = ccw(a, b, u);
    m.triangles[t1] = ccw(a, b, v);
    flipped = true;
    break;
  }
  ASSERT_TRUE(flipped);
  const auto r = pdd::verify(m, d, options(1.0)); // the flip may make a triangle too large
  EXPECT_FALSE(r.ok());
  EXPECT_GE(r.delaunay_violations, 1u);
  EXPECT_EQ(r.orientation_violations, 0u);
  EXPECT_EQ(r.nonmanifold_edges, 0u);
  EXPECT_TRUE(r.area_ok);
  ASSERT_FALSE(r.messages.empty());
  EXPECT_NE(r.messages.back().find("not locally Delaunay"), std::string::npos) << describe(r);
}

TEST(Verify, DetectsAMissingTriangle) {
  const auto d = pdd::test::two_holes();
  auto m = mesh_of(d, 0.01);
  // Remove a triangle with no edge on the boundary.
  const auto inner = interior_edges(m);
  std::map<index_t, int> interior_count;
  for (const auto& e : inner) {
    ++interior_count[e[2]];
    ++interior_count[e[3]];
  }
  index_t victim = 0;
  for (const auto& [t, n] : interior_count)
    if (n == 3) {
      victim = t;
      break;
    }
  m.triangles.erase(m.triangles.begin() + victim);
  m.triangle_markers.pop_back();
  const auto r = pdd::verify(m, d, options(0.01));
  EXPECT_FALSE(r.ok());
  EXPECT_FALSE(r.area_ok);
  EXPECT_LT(r.area_mesh, r.area_domain);
  EXPECT_EQ(r.nonmanifold_edges, 3u) << describe(r);
}

TEST(Verify, DetectsSegmentsOfAnotherDomain) {
  // A mesh whose boundary segments were split, checked against the PSLG with one corner
  // moved: the segments at that corner are no longer unions of mesh edges.
  pdd::pslg d;
  d.add_loop(std::vector<point>{{0, 0}, {10, 0}, {10, 6}, {0, 6}}, 1);
  auto with_vertex = d;
  with_vertex.add_vertex({5, 0.01});
  const auto res = pdd::cgal::mesher{}.mesh(with_vertex, {}, pdd::uniform_sizing{});
  ASSERT_FALSE(res.split_segments.empty());
  EXPECT_TRUE(pdd::verify(res.mesh, d).ok()) << describe(pdd::verify(res.mesh, d));
  auto moved = d;
  moved.vertices[1] = {10, 0.5};
  const auto r = pdd::verify(res.mesh, moved);
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.missing_segments, 2u) << describe(r);
  EXPECT_FALSE(r.area_ok);
  // A vertex moved along its segment's line (the mesh lacks it): still missing.
  auto along = d;
  along.vertices[1] = {9, 0};
  const auto r2 = pdd::verify(res.mesh, along);
  EXPECT_GE(r2.missing_segments, 1u);
}

TEST(Verify, DetectsAClockwiseTriangle) {
  const auto d = pdd::test::l_shape();
  auto m = mesh_of(d, 0.05);
  std::swap(m.triangles[3][0], m.triangles[3][1]);
  const auto r = pdd::verify(m, d, options(0.05));
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.orientation_violations, 1u);
  ASSERT_FALSE(r.messages.empty());
  EXPECT_NE(r.messages[0].find("triangle 3"), std::string::npos) << r.messages[0];
}

TEST(Verify, DetectsADuplicateVertex) {
  const auto d = pdd::test::l_shape();
  auto m = mesh_of(d, 0.05);
  m.vertices.push_back(m.vertices[5]);
  m.vertex_markers.push_back(0);
  const auto r = pdd::verify(m, d, options(0.05));
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.duplicate_vertices, 1u);
  EXPECT_EQ(r.orientation_violations + r.delaunay_violations + r.nonmanifold_edges, 0u);
}

TEST(Verify, DetectsATriangleOverTheAreaBound) {
  const auto d = pdd::test::square_with_hole();
  const auto m = mesh_of(d, 0.01);
  const auto st = pdd::compute_statistics(m);
  const auto r = pdd::verify(m, d, options(st.max_area * 0.999));
  EXPECT_FALSE(r.ok());
  EXPECT_GE(r.area_violations, 1u);
  EXPECT_EQ(r.quality_violations, 0u);
  // With a sizing field that is smaller on the right half only.
  const pdd::analytic_sizing s{[](point p) { return p.x > 1.5 ? 0.001 : 1.0; }};
  const auto r2 = pdd::verify(m, d, options(0.01), s);
  EXPECT_GE(r2.area_violations, 1u);
  EXPECT_TRUE(pdd::verify(m, d, options(0.01)).ok());
}

TEST(Verify, DetectsABadAngle) {
  const auto d = pdd::test::square_with_hole();
  const auto m = mesh_of(d, 0.01);
  pdd::verify_options o = options(0.01);
  o.criteria.min_angle_deg = 35;
  const auto r = pdd::verify(m, d, o);
  EXPECT_FALSE(r.ok());
  EXPECT_GE(r.quality_violations, 1u);
  // A hand-made sliver: a valid Delaunay triangulation of a thin rectangle.
  pdd::pslg thin;
  thin.add_loop(std::vector<point>{{0, 0}, {1, 0}, {1, 0.05}, {0, 0.05}}, 1);
  pdd::triangle_mesh sliver;
  sliver.vertices = thin.vertices;
  sliver.vertex_markers = thin.vertex_markers;
  sliver.triangles = {{0, 1, 2}, {0, 2, 3}};
  sliver.triangle_markers = {0, 0};
  const auto r2 = pdd::verify(sliver, thin);
  EXPECT_EQ(r2.quality_violations, 2u);
  EXPECT_EQ(r2.delaunay_violations, 0u);
  EXPECT_TRUE(r2.area_ok);
  EXPECT_EQ(r2.missing_segments + r2.nonmanifold_edges + r2.orientation_violations, 0u);
}

TEST(Verify, ReportsAtMostMaxReportedMessages) {
  const auto d = pdd::key_domain();
  const auto m = mesh_of(d, 0.001);
  pdd::verify_options o = options(1e-6);
  o.max_reported = 5;
  const auto r = pdd::verify(m, d, o);
  EXPECT_EQ(r.area_violations, m.triangles.size());
  EXPECT_EQ(r.messages.size(), 5u);
}

TEST(Verify, DetectsMalformedTriangles) {
  const auto d = pdd::test::unit_square();
  auto m = mesh_of(d, 0.1);
  m.triangles.push_back({0, 0, 1});
  m.triangles.push_back({0, 1, 999});
  m.triangle_markers.resize(m.triangles.size(), 0);
  const auto r = pdd::verify(m, d, options(0.1));
  EXPECT_EQ(r.orientation_violations, 2u);
  EXPECT_FALSE(r.ok());
}

} // namespace verify_test
