// Triangle's -D (conforming Delaunay: every triangle Delaunay against every vertex of the mesh,
// CGAL's exact in-circle predicate) and -S (at most N Steiner points) through
// pdd::triangle::triangulate.
#include <pdd/core/kernel.hpp>
#include <pdd/errors.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/mesh/quality.hpp>
#include <pdd/triangle/triangulate.hpp>

#include <gtest/gtest.h>

#include "test_support.hpp"

#include <algorithm>
#include <array>
#include <cstddef>
#include <set>
#include <string>
#include <vector>

namespace conforming_test {
namespace tri = pdd::triangle;

#ifdef PDD_PERMISSIVE
// D and S mesh on CGAL's Mesh_2, which a permissive build leaves out: refused, named.
TEST(Conforming, RefusedInAPermissiveBuild) {
  pdd::pslg g;
  g.add_loop(std::array<pdd::point, 3>{{{0, 0}, {1, 0}, {0, 1}}}, 1);
  for (const char* sw : {"pD", "pq30S10"}) {
    try {
      tri::triangulate(g, tri::parse_switches(sw));
      ADD_FAILURE() << sw << " was not refused";
    } catch (const tri::switch_error& e) {
      EXPECT_NE(std::string(e.what()).find("PDD_PERMISSIVE"), std::string::npos) << e.what();
    }
  }
}
#else

namespace {

/// Triangles with a vertex of the mesh strictly inside their circumcircle (exact predicate;
/// every vertex, used or not, is looked at). O(triangles * vertices): small meshes only.
std::size_t delaunay_violations(const pdd::triangle_mesh& m) {
  std::vector<pdd::epick::Point_2> p;
  for (const pdd::point& v : m.vertices)
    p.emplace_back(v.x, v.y);
  std::size_t bad = 0;
  for (const auto& t : m.triangles)
    for (std::size_t v = 0; v < p.size(); ++v) {
      if (v == t[0] || v == t[1] || v == t[2]) continue;
      if (CGAL::side_of_oriented_circle(p[t[0]], p[t[1]], p[t[2]], p[v]) ==
          CGAL::ON_POSITIVE_SIDE) {
        ++bad;
        break;
      }
    }
  return bad;
}

double mesh_area(const pdd::triangle_mesh& m) {
  double sum = 0.0;
  for (const auto& t : m.triangles) {
    const pdd::point a = m.vertices[t[0]], b = m.vertices[t[1]], c = m.vertices[t[2]];
    sum += 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  }
  return sum;
}

/// A rectangle [0,2]x[0,1] with a narrow notch from the top down to (1, 0.05); a vertex of its
/// right wall (1.03, 0.6) lies in the diametral circle of the left wall, so the constrained
/// Delaunay triangulation is not Delaunay. The notch's walls have marker 5, the rest 1.
pdd::pslg notch() {
  pdd::pslg g;
  const std::array<pdd::point, 8> p{
      {{0, 0}, {2, 0}, {2, 1}, {1.05, 1}, {1.03, 0.6}, {1, 0.05}, {0.95, 1}, {0, 1}}};
  for (const pdd::point& v : p)
    g.add_vertex(v, 0);
  for (pdd::index_t i = 0; i < 8; ++i)
    g.add_segment(i, (i + 1) % 8, i >= 3 && i <= 5 ? 5 : 1);
  return g;
}

/// The area of the notch's polygon (the shoelace formula over its vertices, in order).
double notch_area() {
  const pdd::pslg g = notch();
  double twice = 0.0;
  for (std::size_t i = 0; i < g.vertices.size(); ++i) {
    const pdd::point a = g.vertices[i], b = g.vertices[(i + 1) % g.vertices.size()];
    twice += a.x * b.y - a.y * b.x;
  }
  return 0.5 * twice;
}

/// A square with a square hole (no input angle below 90 degrees).
/// The triangles of m, each from its smallest vertex id (same orientation), in a set.
std::set<std::array<pdd::index_t, 3>> triangle_set(const pdd::triangle_mesh& m) {
  std::set<std::array<pdd::index_t, 3>> out;
  for (std::array<pdd::index_t, 3> t : m.triangles) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    out.insert(t);
  }
  return out;
}

pdd::pslg holed_square() {
  pdd::pslg g;
  g.add_loop(std::array<pdd::point, 4>{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}, 2);
  g.add_loop(std::array<pdd::point, 4>{{{0.4, 0.4}, {0.6, 0.4}, {0.6, 0.6}, {0.4, 0.6}}}, 3);
  g.holes.push_back({0.5, 0.5});
  return g;
}

} // namespace

TEST(Conforming, PAloneIsNotDelaunayOnTheNotchButPDIs) {
  const pdd::pslg g = notch();
  const auto p = tri::triangulate(g, tri::parse_switches("p"));
  EXPECT_GT(delaunay_violations(p.mesh), 0u) << "the notch's CDT is not Delaunay";
  const auto d = tri::triangulate(g, tri::parse_switches("pD"));
  EXPECT_EQ(delaunay_violations(d.mesh), 0u);
  EXPECT_GT(d.mesh.vertices.size(), g.vertices.size()) << "a wall is split";
  for (std::size_t i = 0; i < g.vertices.size(); ++i)
    EXPECT_EQ(d.mesh.vertices[i], g.vertices[i]) << "input vertices first, in order";
  EXPECT_NEAR(mesh_area(d.mesh), notch_area(), 1e-12);
  EXPECT_NEAR(mesh_area(p.mesh), notch_area(), 1e-12);
}

/// True when p lies on a wall of the notch, not at its top (y = 1) or its bottom (y = 0).
bool on_notch_wall(pdd::point p) {
  return p.x > 0.94 && p.x < 1.06 && p.y > 0.0 && p.y < 1.0;
}

TEST(Conforming, SplitSegmentsKeepTheirMarkers) {
  const pdd::pslg g = notch();
  const auto d = tri::triangulate(g, tri::parse_switches("pD"));
  std::size_t fives = 0;
  for (const pdd::mesh_edge& e : d.mesh.segments) {
    const pdd::point a = d.mesh.vertices[e.a], b = d.mesh.vertices[e.b];
    const bool wall = (on_notch_wall(a) || on_notch_wall(b)) && a.x > 0.94 && a.x < 1.06 &&
                      b.x > 0.94 && b.x < 1.06;
    EXPECT_EQ(e.marker, wall ? 5 : 1) << e.a << "-" << e.b;
    fives += e.marker == 5;
  }
  EXPECT_GT(fives, 3u) << "a split wall has more than three pieces";
  for (std::size_t v = g.vertices.size(); v < d.mesh.vertices.size(); ++v)
    EXPECT_EQ(d.mesh.vertex_markers[v], on_notch_wall(d.mesh.vertices[v]) ? 5 : 1)
        << "a Steiner vertex on a segment has its marker";
}

TEST(Conforming, QualityAndAreaBoundsHoldWithD) {
  const pdd::pslg g = holed_square();
  const auto m = tri::triangulate(g, tri::parse_switches("pq30a0.002D")).mesh;
  EXPECT_EQ(delaunay_violations(m), 0u);
  EXPECT_NEAR(mesh_area(m), 0.96, 1e-12);
  const pdd::mesh_statistics s = pdd::compute_statistics(m);
  EXPECT_GE(s.min_angle_deg, 30.0 - 1e-9);
  EXPECT_LE(s.max_area, 0.002);
  const auto n = tri::triangulate(notch(), tri::parse_switches("pqa0.01D")).mesh;
  EXPECT_EQ(delaunay_violations(n), 0u);
  EXPECT_NEAR(mesh_area(n), notch_area(), 1e-12);
  EXPECT_LE(pdd::compute_statistics(n).max_area, 0.01);
}

TEST(Conforming, DOnTrianglesExamples) {
  const auto dir = pdd::test::shared_data_dir();
  if (dir.empty()) GTEST_SKIP() << "../shared/data absent";
  for (const char* name : {"triangle_face.poly", "triangle_A.poly"}) {
    const pdd::pslg g = pdd::read_poly(dir / name);
    const auto p = tri::triangulate(g, tri::parse_switches("p"));
    for (const char* sw : {"pD", "pqD"}) {
      const auto d = tri::triangulate(g, tri::parse_switches(sw));
      EXPECT_EQ(delaunay_violations(d.mesh), 0u) << name << " -" << sw;
      EXPECT_NEAR(mesh_area(d.mesh), mesh_area(p.mesh), 1e-9 * mesh_area(p.mesh)) << name;
    }
  }
}

TEST(Conforming, SteinerBudgetCapsTheCount) {
  const pdd::pslg g = holed_square();
  const std::size_t n = g.vertices.size();
  const auto full = tri::triangulate(g, tri::parse_switches("pq30a0.001"));
  ASSERT_GT(full.mesh.vertices.size(), n + 40);
  for (const char* sw : {"pq30a0.001S40", "pq30a0.001DS40"}) {
    const auto t = tri::triangulate(g, tri::parse_switches(sw));
    EXPECT_EQ(t.mesh.vertices.size(), n + 40) << sw;
    EXPECT_NEAR(mesh_area(t.mesh), 0.96, 1e-12) << sw;
  }
  const auto none = tri::triangulate(g, tri::parse_switches("pq30S0"));
  EXPECT_EQ(none.mesh.vertices, g.vertices) << "-S0: no Steiner point";
  EXPECT_EQ(triangle_set(none.mesh),
            triangle_set(tri::triangulate(g, tri::parse_switches("p")).mesh)); // in any order
  const auto ample = tri::triangulate(g, tri::parse_switches("pq30a0.01S100000"));
  EXPECT_LT(ample.mesh.vertices.size(), n + 100000);
  EXPECT_GE(pdd::compute_statistics(ample.mesh).min_angle_deg, 30.0 - 1e-9);
  const auto d = tri::triangulate(notch(), tri::parse_switches("pDS1"));
  EXPECT_EQ(d.mesh.vertices.size(), notch().vertices.size() + 1) << "D stops at the budget too";
}

/// A needle (the regressions' needle-01.poly: an angle of about 1e-8 degrees): a refinement that
/// must keep every segment Delaunay splits its sides without end (Triangle's -pqD runs on and
/// on), so -pqD stops at the runaway cap with pdd::limit_error instead of running until memory
/// runs out, while a budget below the cap (S) still ends with exactly that many points.
TEST(Conforming, ARefinementThatDoesNotEndStopsWithALimitError) {
  pdd::pslg g;
  g.add_loop(std::array<pdd::point, 3>{{{0, 1}, {1, 0}, {0.5, 4444444422.0}}}, 1);
  try {
    (void)tri::triangulate(g, tri::parse_switches("pqD"));
    ADD_FAILURE() << "-pqD on the needle ended";
  } catch (const pdd::limit_error& e) {
    EXPECT_NE(std::string(e.what()).find("did not end"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("S"), std::string::npos) << e.what();
  }
  const auto capped = tri::triangulate(g, tri::parse_switches("pqDS50"));
  EXPECT_EQ(capped.mesh.vertices.size(), 3u + 50u);
}

#endif // PDD_PERMISSIVE

} // namespace conforming_test
