// Tests of the DelaunayMesher models (pdd::cgal::mesher, pdd::native::mesher): every test runs
// on every kernel (kernel_types.hpp).
#include "test_domains.hpp"
#include "test_support.hpp"

#include "kernel_types.hpp"
#include <pdd/geometry/model_domains.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/mesh/quality.hpp>
#include <pdd/mesh/verify.hpp>
#include <pdd/sizing/analytic.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <map>
#include <set>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace mesher_test {
namespace {

using pdd::index_t;
using pdd::point;

bool bitwise_equal(const pdd::mesher_result& x, const pdd::mesher_result& y) {
  const auto& a = x.mesh;
  const auto& b = y.mesh;
  if (a.vertices.size() != b.vertices.size()) return false;
  if (std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(point)) != 0)
    return false;
  const auto seg_eq = [](const pdd::mesh_edge& p, const pdd::mesh_edge& q) {
    return p.a == q.a && p.b == q.b && p.marker == q.marker;
  };
  return a.vertex_markers == b.vertex_markers && a.triangles == b.triangles &&
         a.triangle_markers == b.triangle_markers &&
         std::equal(a.segments.begin(), a.segments.end(), b.segments.begin(), b.segments.end(),
                    seg_eq) &&
         x.split_segments == y.split_segments;
}

std::set<std::pair<index_t, index_t>> mesh_edges(const pdd::triangle_mesh& m) {
  std::set<std::pair<index_t, index_t>> e;
  for (const auto& t : m.triangles)
    for (int i = 0; i < 3; ++i)
      e.insert(
          std::minmax(t[static_cast<std::size_t>(i)], t[static_cast<std::size_t>((i + 1) % 3)]));
  return e;
}

/// Every property the DelaunayMesher concept promises, for a domain with input angles >= 60.
template <class S>
void expect_good_mesh(const pdd::pslg& d, const pdd::mesh_criteria& c, const S& sizing,
                      const pdd::mesher_result& r, const std::string& what) {
  SCOPED_TRACE(what);
  const auto& m = r.mesh;
  const pdd::verification_report rep = pdd::verify(m, d, {.criteria = c}, sizing);
  EXPECT_TRUE(rep.ok()) << [&] {
    std::string s;
    for (const auto& msg : rep.messages)
      s += msg + "\n";
    return s;
  }();
  const auto st = pdd::compute_statistics(m, sizing);
  EXPECT_GE(st.min_angle_deg, c.min_angle_deg - 1e-9);
  EXPECT_LE(st.max_area, c.max_area * (1 + 1e-12));
  EXPECT_LE(st.max_area_ratio, 1 + 1e-12);
  EXPECT_GT(st.triangles, 0u);
  // Input vertices first, bit for bit, with their markers.
  ASSERT_GE(m.vertices.size(), d.vertices.size());
  EXPECT_EQ(std::memcmp(m.vertices.data(), d.vertices.data(), d.vertices.size() * sizeof(point)),
            0);
  for (std::size_t i = 0; i < d.vertices.size(); ++i)
    EXPECT_EQ(m.vertex_markers[i], d.vertex_markers[i]);
  EXPECT_EQ(m.vertex_markers.size(), m.vertices.size());
  EXPECT_EQ(m.triangle_markers, std::vector<int>(m.triangles.size(), 0));
  // split_segments lists exactly the input segments that are not mesh edges.
  const auto edges = mesh_edges(m);
  std::vector<index_t> split;
  for (index_t s = 0; s < d.segments.size(); ++s)
    if (!edges.count(std::minmax(d.segments[s].a, d.segments[s].b))) split.push_back(s);
  EXPECT_EQ(r.split_segments, split);
  // mesh.segments are mesh edges; every boundary edge is one of them.
  std::set<std::pair<index_t, index_t>> seg_edges;
  std::set<int> seg_markers;
  for (const auto& s : d.segments)
    seg_markers.insert(s.marker);
  for (const auto& e : m.segments) {
    EXPECT_LT(e.a, e.b);
    EXPECT_TRUE(edges.count({e.a, e.b}));
    EXPECT_TRUE(seg_markers.count(e.marker));
    seg_edges.insert({e.a, e.b});
  }
  std::map<std::pair<index_t, index_t>, int> uses;
  for (const auto& t : m.triangles)
    for (int i = 0; i < 3; ++i)
      ++uses[std::minmax(t[static_cast<std::size_t>(i)], t[static_cast<std::size_t>((i + 1) % 3)])];
  for (const auto& [e, n] : uses)
    if (n == 1) {
      EXPECT_TRUE(seg_edges.count(e)) << e.first << " " << e.second;
    }
}

pdd::mesh_criteria criteria_with_area(double a) {
  pdd::mesh_criteria c;
  c.max_area = a;
  return c;
}

template <class M>
class Mesher : public ::testing::Test {};
TYPED_TEST_SUITE(Mesher, pdd::test::kernel_types, pdd::test::kernel_names);

} // namespace

TYPED_TEST(Mesher, ModelsTheConcept) {
  static_assert(pdd::DelaunayMesher<TypeParam>);
}

TYPED_TEST(Mesher, HandMadeDomains) {
  const std::vector<std::pair<std::string, pdd::pslg>> domains{
      {"square", pdd::test::unit_square()},
      {"square with hole", pdd::test::square_with_hole()},
      {"L", pdd::test::l_shape()},
      {"two holes", pdd::test::two_holes()},
      {"markers", pdd::test::marker_polygon()},
      {"key", pdd::key_domain()},
      {"pipe", pdd::pipe_domain(96, 12)}};
  for (const auto& [name, d] : domains) {
    for (const double a : {std::numeric_limits<double>::infinity(), 0.01, 0.002}) {
      const auto c = criteria_with_area(a);
      const auto r = TypeParam{}.mesh(d, c, pdd::uniform_sizing{});
      expect_good_mesh(d, c, pdd::uniform_sizing{}, r, name + " A=" + std::to_string(a));
    }
  }
}

TYPED_TEST(Mesher, SquareWithoutBoundIsTwoTriangles) {
  const auto d = pdd::test::unit_square();
  const auto r = TypeParam{}.mesh(d, {}, pdd::uniform_sizing{});
  EXPECT_EQ(r.mesh.triangles.size(), 2u);
  EXPECT_EQ(r.mesh.vertices.size(), 4u);
  EXPECT_TRUE(r.split_segments.empty());
  EXPECT_EQ(r.mesh.segments.size(), 4u);
}

TYPED_TEST(Mesher, HoleRegionsAreEmpty) {
  const auto d = pdd::test::square_with_hole();
  const auto r = TypeParam{}.mesh(d, criteria_with_area(0.01), pdd::uniform_sizing{});
  for (const auto& t : r.mesh.triangles) {
    const auto& v = r.mesh.vertices;
    const point c{(v[t[0]].x + v[t[1]].x + v[t[2]].x) / 3, (v[t[0]].y + v[t[1]].y + v[t[2]].y) / 3};
    EXPECT_FALSE(c.x > 1 && c.x < 2 && c.y > 1 && c.y < 2);
  }
  // The same hole given by nesting alone (no hole point) is also left out.
  auto nested = d;
  nested.holes.clear();
  const auto r2 = TypeParam{}.mesh(nested, criteria_with_area(0.01), pdd::uniform_sizing{});
  EXPECT_TRUE(bitwise_equal(r, r2));
}

TYPED_TEST(Mesher, SteinerMarkersFollowSegments) {
  const auto d = pdd::test::marker_polygon();
  const auto r = TypeParam{}.mesh(d, criteria_with_area(0.005), pdd::uniform_sizing{});
  const auto& m = r.mesh;
  ASSERT_FALSE(r.split_segments.empty());
  std::size_t on_segment = 0;
  for (std::size_t v = d.vertices.size(); v < m.vertices.size(); ++v) {
    // Which input segment is the vertex on (within rounding)?
    int expected = 0;
    for (const auto& s : d.segments) {
      const point a = d.vertices[s.a], b = d.vertices[s.b], p = m.vertices[v];
      if (pdd::test::dist_point_segment(p, a, b) < 1e-12) expected = s.marker;
    }
    EXPECT_EQ(m.vertex_markers[v], expected) << v;
    if (expected != 0) ++on_segment;
  }
  EXPECT_GT(on_segment, 0u);
  for (const auto& e : m.segments) {
    const point p{(m.vertices[e.a].x + m.vertices[e.b].x) / 2,
                  (m.vertices[e.a].y + m.vertices[e.b].y) / 2};
    int expected = -1;
    for (const auto& s : d.segments)
      if (pdd::test::dist_point_segment(p, d.vertices[s.a], d.vertices[s.b]) < 1e-12)
        expected = s.marker;
    EXPECT_EQ(e.marker, expected);
  }
}

TYPED_TEST(Mesher, RandomDomainsWithLargeAngles) {
  for (std::uint64_t seed = 1; seed <= 24; ++seed) {
    const auto d = pdd::test::random_domain_60(seed);
    const double a = seed % 3 == 0 ? 0.02 : 0.002;
    const auto c = criteria_with_area(a);
    const auto r = TypeParam{}.mesh(d, c, pdd::uniform_sizing{});
    expect_good_mesh(d, c, pdd::uniform_sizing{}, r, "seed " + std::to_string(seed));
  }
}

TYPED_TEST(Mesher, GradedSizingField) {
  const pdd::analytic_sizing s{[](point p) { return 1e-4 + 0.02 * (p.x * p.x + p.y * p.y); }};
  for (std::uint64_t seed = 100; seed < 104; ++seed) {
    const auto d = pdd::test::random_domain_60(seed);
    pdd::mesh_criteria c;
    c.min_angle_deg = 25;
    const auto r = TypeParam{}.mesh(d, c, s);
    expect_good_mesh(d, c, s, r, "graded seed " + std::to_string(seed));
  }
}

TYPED_TEST(Mesher, Deterministic) {
  const auto d = pdd::pipe_domain(192, 24);
  const auto c = criteria_with_area(2e-4);
  const auto r1 = TypeParam{}.mesh(d, c, pdd::uniform_sizing{});
  const auto r2 = TypeParam{}.mesh(d, c, pdd::uniform_sizing{});
  EXPECT_GT(r1.mesh.triangles.size(), 10000u);
  EXPECT_TRUE(bitwise_equal(r1, r2));
}

TYPED_TEST(Mesher, ConcurrentInstancesMatchSequential) {
  std::vector<pdd::pslg> inputs{pdd::pipe_domain(96, 12), pdd::key_domain(),
                                pdd::test::random_domain_60(7), pdd::test::two_holes()};
  const auto c = criteria_with_area(1e-3);
  std::vector<pdd::mesher_result> sequential, concurrent(inputs.size());
  for (const auto& d : inputs)
    sequential.push_back(TypeParam{}.mesh(d, c, pdd::uniform_sizing{}));
  for (int round = 0; round < 3; ++round) {
    std::vector<std::thread> threads;
    for (std::size_t i = 0; i < inputs.size(); ++i)
      threads.emplace_back(
          [&, i] { concurrent[i] = TypeParam{}.mesh(inputs[i], c, pdd::uniform_sizing{}); });
    for (auto& t : threads)
      t.join();
    for (std::size_t i = 0; i < inputs.size(); ++i)
      EXPECT_TRUE(bitwise_equal(sequential[i], concurrent[i])) << "input " << i;
  }
}

TYPED_TEST(Mesher, ReportsASegmentThatMustBeSplit) {
  // A long bottom segment with an input vertex just above its middle: the vertex lies in the
  // segment's diametral circle, so Delaunay refinement must split it.
  pdd::pslg d;
  d.add_loop(std::vector<point>{{0, 0}, {10, 0}, {10, 6}, {0, 6}}, 1);
  const pdd::pslg domain = d; // the same domain without the free vertex
  d.add_vertex({5, 0.01}, 7);
  const auto r = TypeParam{}.mesh(d, {}, pdd::uniform_sizing{});
  ASSERT_FALSE(r.split_segments.empty());
  EXPECT_EQ(r.split_segments[0], 0u);
  expect_good_mesh(domain, {}, pdd::uniform_sizing{}, pdd::mesher_result{r.mesh, r.split_segments},
                   "split bottom");
}

TYPED_TEST(Mesher, PreSplitChainIsNotSplit) {
  // A 4 x 1 rectangle whose sides are pre-split into pieces of length 0.1, as the decoupling
  // method splits interfaces: under an area bound whose triangles are larger than the pieces
  // need, no piece is encroached and none is split.
  std::vector<point> pts;
  for (int i = 0; i < 40; ++i)
    pts.push_back({0.1 * i, 0});
  for (int i = 0; i < 10; ++i)
    pts.push_back({4, 0.1 * i});
  for (int i = 40; i > 0; --i)
    pts.push_back({0.1 * i, 1});
  for (int i = 10; i > 0; --i)
    pts.push_back({0, 0.1 * i});
  pdd::pslg d;
  d.add_loop(pts, 3);
  const auto c = criteria_with_area(0.02);
  const auto r = TypeParam{}.mesh(d, c, pdd::uniform_sizing{});
  EXPECT_TRUE(r.split_segments.empty());
  EXPECT_EQ(r.mesh.segments.size(), d.segments.size());
  expect_good_mesh(d, c, pdd::uniform_sizing{}, r, "pre-split chain");
}

TYPED_TEST(Mesher, EncroachmentFromOutsideTheDomainIsIgnored) {
  // A U whose notch (outside the domain) is 0.2 wide: the vertex (1.2, 1.25) on the right
  // wall lies in the diametral circle of the left wall's segment (1, 0.5)-(1, 2), but on the
  // far side of the notch. CGAL's two-sided test would split that segment; ours must not.
  pdd::pslg d;
  d.add_loop(
      std::vector<point>{
          {0, 0}, {2.2, 0}, {2.2, 2}, {1.2, 2}, {1.2, 1.25}, {1.2, 0.5}, {1, 0.5}, {1, 2}, {0, 2}},
      1);
  const auto r = TypeParam{}.mesh(d, {}, pdd::uniform_sizing{});
  EXPECT_TRUE(std::find(r.split_segments.begin(), r.split_segments.end(), 6u) ==
              r.split_segments.end());
  expect_good_mesh(d, {}, pdd::uniform_sizing{}, r, "U");
}

TYPED_TEST(Mesher, RejectsUnusableInput) {
  const TypeParam m;
  const pdd::uniform_sizing s;
  auto dup = pdd::test::unit_square();
  dup.add_vertex({1, 1});
  EXPECT_THROW(m.mesh(dup, {}, s), pdd::meshing_error);
  auto crossing = pdd::test::unit_square();
  crossing.add_segment(0, 2);
  crossing.add_segment(1, 3);
  EXPECT_THROW(m.mesh(crossing, {}, s), pdd::meshing_error);
  auto through = pdd::test::unit_square();
  const auto mid = through.add_vertex({0.5, 0});
  (void)mid;
  EXPECT_THROW(m.mesh(through, {}, s), pdd::meshing_error);
  auto bad_index = pdd::test::unit_square();
  bad_index.add_segment(0, 9);
  EXPECT_THROW(m.mesh(bad_index, {}, s), pdd::meshing_error);
  auto nan = pdd::test::unit_square();
  nan.vertices[2].x = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(m.mesh(nan, {}, s), pdd::meshing_error);
  pdd::mesh_criteria bad;
  bad.min_angle_deg = 61;
  EXPECT_THROW(m.mesh(pdd::test::unit_square(), bad, s), pdd::meshing_error);
  bad = {};
  bad.max_area = 0;
  EXPECT_THROW(m.mesh(pdd::test::unit_square(), bad, s), pdd::meshing_error);
  try {
    m.mesh(dup, {}, s);
  } catch (const pdd::meshing_error& e) {
    EXPECT_EQ(e.subdomain(), -1);
    EXPECT_NE(std::string(e.what()).find("coincide"), std::string::npos);
  }
}

TYPED_TEST(Mesher, DegenerateInputGivesNoTriangles) {
  pdd::pslg d;
  d.add_vertex({0, 0});
  d.add_vertex({1, 1});
  d.add_segment(0, 1);
  const auto r = TypeParam{}.mesh(d, {}, pdd::uniform_sizing{});
  EXPECT_TRUE(r.mesh.triangles.empty());
  EXPECT_EQ(r.mesh.vertices.size(), 2u);
}

// --- shared test geometries (../shared/data; skipped when absent) -----------------------------

namespace {

pdd::pslg read_shared(const std::string& name) {
  return pdd::read_poly(pdd::test::shared_data_dir() / name);
}

double bbox_area(const pdd::pslg& d) {
  double x0 = d.vertices[0].x, x1 = x0, y0 = d.vertices[0].y, y1 = y0;
  for (const point& p : d.vertices) {
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  }
  return (x1 - x0) * (y1 - y0);
}

template <class M>
class MesherSharedData : public ::testing::Test {};
TYPED_TEST_SUITE(MesherSharedData, pdd::test::kernel_types, pdd::test::kernel_names);

} // namespace

TYPED_TEST(MesherSharedData, AirfoilMeetsEveryBound) {
  // The only shared geometry whose smallest angle on the meshed side (113.6 deg) is >= 60.
  if (pdd::test::shared_data_dir().empty()) GTEST_SKIP() << "../shared/data absent";
  const auto d = read_shared("mesh2d_airfoil_3element.poly");
  for (const double a : {std::numeric_limits<double>::infinity(), 1e-3, 1e-4}) {
    const auto c = criteria_with_area(a);
    const auto r = TypeParam{}.mesh(d, c, pdd::uniform_sizing{});
    expect_good_mesh(d, c, pdd::uniform_sizing{}, r, "airfoil A=" + std::to_string(a));
  }
  const pdd::analytic_sizing graded{[](point p) {
    return 2e-6 + 1e-3 * ((p.x - 0.5) * (p.x - 0.5) + (p.y - 0.5) * (p.y - 0.5));
  }};
  const auto r = TypeParam{}.mesh(d, {}, graded);
  expect_good_mesh(d, {}, graded, r, "airfoil graded");
  EXPECT_TRUE(bitwise_equal(r, TypeParam{}.mesh(d, {}, graded)));
}

TYPED_TEST(MesherSharedData, SmallInputAnglesStillGiveValidMeshes) {
  // Input angles below 60 deg: no quality guarantee near them, but the mesh must still be a
  // conforming constrained Delaunay mesh of exactly the domain within the area bound.
  if (pdd::test::shared_data_dir().empty()) GTEST_SKIP() << "../shared/data absent";
  for (const char* name : {"triangle_A.poly", "lake_superior.poly", "bahamas_islands.poly",
                           "texas.poly", "guitar.poly"}) {
    const auto d = read_shared(name);
    const auto c = criteria_with_area(bbox_area(d) / 2000);
    const auto r = TypeParam{}.mesh(d, c, pdd::uniform_sizing{});
    const auto rep = pdd::verify(r.mesh, d, {.criteria = c});
    SCOPED_TRACE(name);
    EXPECT_EQ(rep.delaunay_violations, 0u);
    EXPECT_EQ(rep.orientation_violations, 0u);
    EXPECT_EQ(rep.missing_segments, 0u);
    EXPECT_EQ(rep.duplicate_vertices, 0u);
    EXPECT_EQ(rep.area_violations, 0u);
    EXPECT_EQ(rep.nonmanifold_edges, 0u);
    EXPECT_TRUE(rep.area_ok);
    EXPECT_LE(rep.quality_violations, 2u); // triangles at input angles below 20.7 deg
    EXPECT_EQ(
        std::memcmp(r.mesh.vertices.data(), d.vertices.data(), d.vertices.size() * sizeof(point)),
        0);
  }
}

TYPED_TEST(MesherSharedData, DanglingSegmentsAndFreeVerticesAreMeshed) {
  // face.poly has dangling segments and isolated vertices, clusters.poly a star of dangling
  // segments: they are constraints inside the domain (both sides meshed).
  if (pdd::test::shared_data_dir().empty()) GTEST_SKIP() << "../shared/data absent";
  for (const char* name : {"triangle_face.poly", "cgal_clusters.poly"}) {
    SCOPED_TRACE(name);
    const auto d = read_shared(name);
    const auto r =
        TypeParam{}.mesh(d, criteria_with_area(bbox_area(d) / 1000), pdd::uniform_sizing{});
    const auto edges = mesh_edges(r.mesh);
    std::vector<index_t> split;
    for (index_t s = 0; s < d.segments.size(); ++s)
      if (!edges.count(std::minmax(d.segments[s].a, d.segments[s].b))) split.push_back(s);
    EXPECT_EQ(r.split_segments, split);
    const auto st = pdd::compute_statistics(r.mesh);
    EXPECT_GT(st.triangles, 100u);
    EXPECT_LE(st.max_area, bbox_area(d) / 1000 * (1 + 1e-12));
    // Every input vertex is a mesh vertex used by a triangle.
    std::vector<char> used(r.mesh.vertices.size(), 0);
    for (const auto& t : r.mesh.triangles)
      for (const index_t v : t)
        used[v] = 1;
    for (std::size_t v = 0; v < d.vertices.size(); ++v)
      EXPECT_TRUE(used[v]) << v;
  }
}

} // namespace mesher_test
