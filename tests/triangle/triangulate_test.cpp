// pdd::triangle::triangulate and make_file_names: Triangle's semantics of p, q, a, a alone,
// A, O, j, n on pdd meshes, Triangle's output file names, and determinism across threads.
#include <pdd/io/poly.hpp>
#include <pdd/io/previous_mesh.hpp>
#include <pdd/mesh/quality.hpp>
#include <pdd/mesh/verify.hpp>
#include <pdd/triangle/file_names.hpp>
#include <pdd/triangle/triangulate.hpp>

#include <gtest/gtest.h>

#include "test_support.hpp"
#include "verified.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

namespace triangulate_test {
namespace tri = pdd::triangle;

namespace {

pdd::pslg square_loop(pdd::pslg g, double x0, double y0, double side, int marker) {
  const std::array<pdd::point, 4> p{
      {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}}};
  g.add_loop(p, marker);
  return g;
}

/// Two disjoint squares [0,1]^2 and [2,3]x[0,1], the second with a square hole.
pdd::pslg two_squares() {
  pdd::pslg g = square_loop({}, 0, 0, 1, 1);
  g = square_loop(std::move(g), 2, 0, 1, 2);
  g = square_loop(std::move(g), 2.25, 0.25, 0.5, 3);
  g.holes.push_back({2.5, 0.5});
  return g;
}

double centroid_x(const pdd::triangle_mesh& m, std::size_t t) {
  const auto& v = m.triangles[t];
  return (m.vertices[v[0]].x + m.vertices[v[1]].x + m.vertices[v[2]].x) / 3.0;
}

double area(const pdd::triangle_mesh& m, std::size_t t) {
  const auto& v = m.triangles[t];
  const pdd::point a = m.vertices[v[0]], b = m.vertices[v[1]], c = m.vertices[v[2]];
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

} // namespace

TEST(Triangulate, QualityAndAreaOnKey) {
  const pdd::pslg key = pdd::read_poly(pdd::test::bundled_data("key.poly"));
  const tri::triangulation t = tri::triangulate(key, tri::parse_switches("pq30a0.01"));
  pdd::mesh_criteria c;
  c.min_angle_deg = 30.0;
  c.max_area = 0.01;
  pdd::test::expect_verified(t.mesh, key, c, "key pq30a0.01");
  EXPECT_GE(pdd::compute_statistics(t.mesh).min_angle_deg, 30.0);
  // Triangle's numbering: the input vertices first, in input order, with their markers.
  ASSERT_GE(t.mesh.vertices.size(), key.vertices.size());
  for (std::size_t i = 0; i < key.vertices.size(); ++i) {
    EXPECT_EQ(t.mesh.vertices[i], key.vertices[i]) << i;
    EXPECT_EQ(t.mesh.vertex_markers[i], key.vertex_markers[i]) << i;
  }
  EXPECT_TRUE(t.triangle_attributes.empty());
  EXPECT_TRUE(t.neighbors.empty());
  ASSERT_EQ(t.runs.size(), 1u);
  EXPECT_EQ(t.runs[0].triangles, t.mesh.triangles.size());
}

TEST(Triangulate, SameArraysForAnyThreadCount) {
  const pdd::pslg pipe = pdd::read_poly(pdd::test::bundled_data("pipe.poly"));
  const auto sw = tri::parse_switches("pq25a0.002An");
  const auto one = tri::triangulate(pipe, sw, {.threads = 1, .subdomains = 8});
  const auto two = tri::triangulate(pipe, sw, {.threads = 2, .subdomains = 8});
  ASSERT_EQ(one.runs[0].subdomains, 8u);
  EXPECT_EQ(one.mesh.vertices, two.mesh.vertices);
  EXPECT_EQ(one.mesh.triangles, two.mesh.triangles);
  EXPECT_EQ(one.neighbors, two.neighbors);
  EXPECT_EQ(one.triangle_attributes, two.triangle_attributes);
  pdd::mesh_criteria c;
  c.min_angle_deg = 25.0;
  c.max_area = 0.002;
  pdd::test::expect_verified(one.mesh, pipe, c, "pipe N=8");
}

TEST(Triangulate, RegionalAttributesAndAreas) {
  pdd::pslg g = two_squares();
  g.regions.push_back({{0.5, 0.5}, 7.0, 0.001});
  g.regions.push_back({{2.1, 0.1}, 9.0, 0.02});
  g.regions.push_back({{2.5, 0.5}, 100.0, 1e-6}); // in the hole: ignored, as in Triangle
  const auto t = tri::triangulate(g, tri::parse_switches("pqAa"));
  ASSERT_EQ(t.triangle_attributes.size(), t.mesh.triangles.size());
  ASSERT_EQ(t.runs.size(), 2u); // the bounds differ: one run per component
  std::size_t left = 0, right = 0;
  for (std::size_t i = 0; i < t.mesh.triangles.size(); ++i) {
    const bool is_left = centroid_x(t.mesh, i) < 1.5;
    EXPECT_EQ(t.triangle_attributes[i], is_left ? 7.0 : 9.0) << i;
    EXPECT_LE(area(t.mesh, i), is_left ? 0.001 : 0.02) << i;
    EXPECT_GT(area(t.mesh, i), 1e-6) << i;
    (is_left ? left : right) += 1;
  }
  EXPECT_GT(left, 1000u); // area 1 under 0.001
  EXPECT_LT(right, left);
  pdd::mesh_criteria c;
  c.max_area = 0.02;
  c.min_angle_deg = 20.0; // Triangle's q without a number (the check was at 20.7 before)
  pdd::test::expect_verified(t.mesh, g, c, "two squares");
  for (std::size_t i = 0; i < g.vertices.size(); ++i)
    EXPECT_EQ(t.mesh.vertices[i], g.vertices[i]) << i;

  // Without 'a' alone the regions' areas do not apply; A alone labels one run's mesh.
  const auto u = tri::triangulate(g, tri::parse_switches("pqA"));
  ASSERT_EQ(u.runs.size(), 1u);
  for (std::size_t i = 0; i < u.mesh.triangles.size(); ++i)
    EXPECT_EQ(u.triangle_attributes[i], centroid_x(u.mesh, i) < 1.5 ? 7.0 : 9.0) << i;
  EXPECT_LT(u.mesh.triangles.size(), 200u);
  // A uniform bound below the regional one wins.
  const auto w = tri::triangulate(g, tri::parse_switches("pqa0.0005a"));
  for (std::size_t i = 0; i < w.mesh.triangles.size(); ++i)
    EXPECT_LE(area(w.mesh, i), 0.0005) << i;
}

TEST(Triangulate, NeighborsAreSymmetricAndAcrossFromTheVertex) {
  const pdd::pslg key = pdd::read_poly(pdd::test::bundled_data("key.poly"));
  const auto t = tri::triangulate(key, tri::parse_switches("pq20a0.005n"));
  ASSERT_EQ(t.neighbors.size(), t.mesh.triangles.size());
  std::size_t boundary = 0;
  for (std::size_t i = 0; i < t.neighbors.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const long long n = t.neighbors[i][static_cast<std::size_t>(k)];
      if (n < 0) {
        ++boundary;
        continue;
      }
      const auto& me = t.mesh.triangles[i];
      const auto& other = t.mesh.triangles[static_cast<std::size_t>(n)];
      // the neighbour holds the edge opposite vertex k and names i back
      int shared = 0, back = 0;
      for (int j = 0; j < 3; ++j) {
        for (int l = 1; l < 3; ++l)
          shared += other[static_cast<std::size_t>(j)] == me[static_cast<std::size_t>((k + l) % 3)];
        back += t.neighbors[static_cast<std::size_t>(n)][static_cast<std::size_t>(j)] ==
                static_cast<long long>(i);
      }
      EXPECT_EQ(shared, 2);
      EXPECT_EQ(back, 1);
    }
  EXPECT_EQ(boundary, t.mesh.segments.size()); // every boundary edge is a subsegment
}

TEST(Triangulate, WithoutPTheVerticesAreTriangulatedAndOMeshesHoles) {
  const pdd::pslg g = two_squares();
  // Without p the twelve vertices are a vertex set: the segments and the hole are not read.
  const auto points = tri::triangulate(g, tri::parse_switches("q"));
  double sum = 0.0;
  for (std::size_t i = 0; i < points.mesh.triangles.size(); ++i)
    sum += area(points.mesh, i);
  EXPECT_NEAR(sum, 3.0, 1e-12); // the hull [0,3]x[0,1], the hole meshed
  // O drops the hole point: as in Triangle, the inner loop is then an internal boundary and
  // the hole is meshed too (one subdomain: the domain is no longer one of closed loops).
  const auto with_hole = tri::triangulate(g, tri::parse_switches("pqa0.1"));
  const auto without = tri::triangulate(g, tri::parse_switches("pOqa0.1"));
  EXPECT_GT(without.mesh.triangles.size(), with_hole.mesh.triangles.size());
  EXPECT_TRUE(without.runs.front().general_domain);
  // O on a domain without holes changes nothing.
  const pdd::pslg sq = square_loop({}, 0, 0, 1, 1);
  EXPECT_EQ(tri::triangulate(sq, tri::parse_switches("pOqa0.1")).mesh.triangles,
            tri::triangulate(sq, tri::parse_switches("pqa0.1")).mesh.triangles);
}

TEST(Triangulate, PAloneIsTheConstrainedDelaunayTriangulation) {
  pdd::pslg g = two_squares(); // with a crack and a well in the first square
  g.add_segment(g.add_vertex({0.2, 0.2}), g.add_vertex({0.8, 0.3}), 7);
  g.add_vertex({0.5, 0.7});
  const auto t = tri::triangulate(g, tri::parse_switches("p"));
  EXPECT_TRUE(t.runs.empty()) << "no refinement run";
  EXPECT_EQ(t.mesh.vertices, g.vertices) << "no Steiner point, input order";
  double sum = 0.0;
  for (std::size_t i = 0; i < t.mesh.triangles.size(); ++i) {
    EXPECT_GT(area(t.mesh, i), 0.0) << "counter-clockwise";
    sum += area(t.mesh, i);
  }
  EXPECT_NEAR(sum, 1.75, 1e-12);
  EXPECT_EQ(t.mesh.segments.size(), g.segments.size()) << "every segment is a mesh edge";
  EXPECT_EQ(t.mesh.segments.back().marker, 7);
  pdd::verify_options vo; // constrained Delaunay, every segment and vertex in the mesh
  vo.criteria.min_angle_deg = 0.0;
  const pdd::verification_report rep = pdd::verify(t.mesh, g, vo);
  EXPECT_TRUE(rep.ok()) << pdd::test::describe(rep);
  EXPECT_EQ(rep.delaunay_violations, 0u);
  // Euler on the two squares (one with a hole, one with a crack and a well): the number of
  // triangles of a triangulation without Steiner points is fixed by the vertices
  EXPECT_EQ(t.mesh.triangles.size(), 8u + 8u);
  // q refines it; A gives the regions' attributes without refining
  EXPECT_GT(tri::triangulate(g, tri::parse_switches("pq")).mesh.vertices.size(), g.vertices.size());
  g.regions.push_back({{2.1, 0.1}, 5.0, -1.0});
  const auto attributed = tri::triangulate(g, tri::parse_switches("pA"));
  EXPECT_EQ(attributed.mesh.triangles, t.mesh.triangles);
  for (std::size_t i = 0; i < attributed.triangle_attributes.size(); ++i)
    EXPECT_EQ(attributed.triangle_attributes[i], centroid_x(t.mesh, i) > 2.0 ? 5.0 : 0.0);
}

TEST(Triangulate, PAloneMatchesTrianglesCountsOnItsExamples) {
  const auto dir = pdd::test::shared_data_dir();
  if (dir.empty()) GTEST_SKIP() << "../shared/data absent";
  // Triangle 1.6: triangle -pQ triangle_face.poly -> 26 vertices, 36 triangles;
  // triangle -pQ triangle_A.poly -> 29 vertices, 29 triangles
  for (const auto& [name, vertices, triangles] :
       {std::tuple{"triangle_face.poly", 26u, 36u}, std::tuple{"triangle_A.poly", 29u, 29u}}) {
    const auto t = tri::triangulate(pdd::read_poly(dir / name), tri::parse_switches("p"));
    EXPECT_EQ(t.mesh.vertices.size(), vertices) << name;
    EXPECT_EQ(t.mesh.triangles.size(), triangles) << name;
  }
}

TEST(Triangulate, QualityMeshesOfItsExamplesHaveTrianglesSize) {
  // Issue 35 item 5: within 15 % of Triangle 1.6's count (or 12 triangles), with the bounds,
  // the domain's area and the constrained Delaunay property checked. Triangle 1.6's counts
  // (triangle -pQ<switches>): under -D (the diametral circle) face -pq makes 76, pdd 78
  // before it refined under the lens as Triangle does.
  const auto dir = pdd::test::shared_data_dir();
  if (dir.empty()) GTEST_SKIP() << "../shared/data absent";
  const std::vector<std::tuple<const char*, const char*, double>> cases{
      {"triangle_face.poly", "pq", 56},      {"triangle_face.poly", "pq25", 72},
      {"triangle_face.poly", "pq30", 132},   {"triangle_face.poly", "pq33", 142},
      {"triangle_face.poly", "pqa20", 1583}, {"triangle_face.poly", "pq30a20", 1619},
      {"triangle_A.poly", "pq", 60},         {"triangle_A.poly", "pq25", 70},
      {"triangle_A.poly", "pq30", 87},       {"triangle_A.poly", "pq33", 128},
      {"triangle_A.poly", "pqa0.001", 132},  {"triangle_A.poly", "pq30a0.001", 147}};
  for (const auto& [name, switches, triangle_count] : cases) {
    const pdd::pslg d = pdd::read_poly(dir / name);
    const tri::switches sw = tri::parse_switches(switches);
    const auto t = tri::triangulate(d, sw);
    const auto n = static_cast<double>(t.mesh.triangles.size());
    const std::string what = std::string(name) + " -" + switches + ": " + std::to_string(n);
    EXPECT_LE(std::abs(n - triangle_count), std::max(12.0, 0.15 * triangle_count)) << what;
    pdd::verify_options o;
    o.criteria.min_angle_deg = sw.min_angle_deg;
    if (sw.max_area > 0) o.criteria.max_area = sw.max_area;
    o.criteria.encroachment = pdd::segment_encroachment::diametral_lens;
    const pdd::verification_report r = pdd::verify(t.mesh, d, o);
    EXPECT_TRUE(r.ok()) << what << "\n" << (r.messages.empty() ? "" : r.messages.front());
  }
}

TEST(Triangulate, SecondOrderNodesSitInTheMiddleOfEveryEdgeOnce) {
  const pdd::pslg key = pdd::read_poly(pdd::test::bundled_data("key.poly"));
  const auto plain = tri::triangulate(key, tri::parse_switches("pqa0.01e"));
  const auto t = tri::triangulate(key, tri::parse_switches("pqa0.01eo2"));
  const std::size_t corners = plain.mesh.vertices.size();
  ASSERT_EQ(t.second_order.size(), t.mesh.triangles.size());
  EXPECT_EQ(t.mesh.triangles, plain.mesh.triangles) << "o2 adds nodes, the corners stay";
  EXPECT_EQ(t.mesh.vertices.size(), corners + plain.edges.size()) << "one node per edge";
  std::vector<int> uses(t.mesh.vertices.size(), 0);
  for (std::size_t i = 0; i < t.mesh.triangles.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      const pdd::index_t n = t.second_order[i][k];
      ASSERT_GE(n, corners);
      ++uses[n];
      const pdd::point a = t.mesh.vertices[t.mesh.triangles[i][(k + 1) % 3]];
      const pdd::point b = t.mesh.vertices[t.mesh.triangles[i][(k + 2) % 3]];
      EXPECT_EQ(t.mesh.vertices[n], (pdd::point{0.5 * (a.x + b.x), 0.5 * (a.y + b.y)}));
    }
  std::size_t boundary = 0;
  for (std::size_t v = corners; v < uses.size(); ++v) {
    EXPECT_TRUE(uses[v] == 1 || uses[v] == 2) << v;
    boundary += uses[v] == 1;
    EXPECT_EQ(t.mesh.vertex_markers[v] != 0, uses[v] == 1) << "marked on the boundary only";
  }
  EXPECT_EQ(boundary, t.mesh.segments.size()) << "key.poly: every boundary edge on a segment";
}

/// The previous mesh of Triangle's -r from a triangulate result.
pdd::previous_mesh previous_of(const tri::triangulation& t) {
  pdd::previous_mesh m;
  m.input.vertices = t.mesh.vertices;
  m.input.vertex_markers = t.mesh.vertex_markers;
  m.triangles = t.mesh.triangles;
  return m;
}

TEST(Triangulate, RefineKeepsTheVerticesAndTheDomain) {
  const pdd::pslg key = pdd::read_poly(pdd::test::bundled_data("key.poly"));
  const auto coarse = tri::triangulate(key, tri::parse_switches("pq"));
  const pdd::previous_mesh prev = previous_of(coarse);
  const auto fine = tri::refine(prev, tri::parse_switches("rq30a0.002"));
  ASSERT_GT(fine.mesh.vertices.size(), prev.input.vertices.size());
  EXPECT_TRUE(std::equal(prev.input.vertices.begin(), prev.input.vertices.end(),
                         fine.mesh.vertices.begin()))
      << "the previous vertices first, in their order";
  pdd::verify_options vo;
  vo.criteria = {.min_angle_deg = 30.0, .max_area = 0.002};
  const pdd::verification_report rep = pdd::verify(fine.mesh, key, vo); // the key's own domain
  EXPECT_TRUE(rep.ok()) << pdd::test::describe(rep);
  // r alone: the same vertices, no Steiner point, as many triangles (Euler)
  const auto same = tri::refine(prev, tri::parse_switches("r"));
  EXPECT_EQ(same.mesh.vertices, prev.input.vertices);
  EXPECT_EQ(same.mesh.triangles.size(), prev.triangles.size());
}

TEST(Triangulate, RefineWithPerTriangleAreasAndAttributes) {
  const pdd::pslg key = pdd::read_poly(pdd::test::bundled_data("key.poly"));
  const auto coarse = tri::triangulate(key, tri::parse_switches("pq"));
  pdd::previous_mesh prev = previous_of(coarse);
  for (std::size_t t = 0; t < prev.triangles.size(); ++t) { // bounded left of x = 0 only
    const bool left = centroid_x(coarse.mesh, t) < 0.0;
    prev.triangle_areas.push_back(left ? 0.0005 : -1.0);
    prev.triangle_attributes.push_back(left ? 1.0 : 2.0);
  }
  const auto r = tri::refine(prev, tri::parse_switches("rqa"));
  ASSERT_EQ(r.triangle_attributes.size(), r.mesh.triangles.size());
  std::size_t bounded = 0;
  for (std::size_t t = 0; t < r.mesh.triangles.size(); ++t) {
    const double attribute = r.triangle_attributes[t];
    ASSERT_TRUE(attribute == 1.0 || attribute == 2.0) << t;
    if (attribute == 1.0) {
      ++bounded;
      EXPECT_LE(area(r.mesh, t), 0.0005 * (1 + 1e-12)) << t;
    }
  }
  EXPECT_GT(bounded, 100u);
  // the ids are checked
  prev.triangles.back()[2] = static_cast<pdd::index_t>(prev.input.vertices.size());
  EXPECT_THROW(tri::refine(prev, tri::parse_switches("rq")), pdd::geometry_error);
}

TEST(Triangulate, VertexAttributesInterpolatedAndBadInputRefusedByPdd) {
  const pdd::pslg key = pdd::read_poly(pdd::test::bundled_data("key.poly"));
  pdd::previous_mesh prev = previous_of(tri::triangulate(key, tri::parse_switches("pq")));
  prev.input.vertex_attribute_count = 1;
  for (const pdd::point& p : prev.input.vertices)
    prev.input.vertex_attributes.push_back(3.0 - p.x + 0.5 * p.y); // linear: reproduced
  const auto r = tri::refine(prev, tri::parse_switches("rqa0.01o2"));
  ASSERT_EQ(r.vertex_attributes.size(), r.mesh.vertices.size());
  for (std::size_t v = 0; v < r.mesh.vertices.size(); ++v)
    EXPECT_NEAR(r.vertex_attributes[v], 3.0 - r.mesh.vertices[v].x + 0.5 * r.mesh.vertices[v].y,
                1e-9)
        << v;
  // crossing segments with attributes: pdd's geometry_error, as without them
  pdd::pslg crossing = square_loop({}, 0, 0, 1, 1);
  crossing.add_segment(0, 2);
  crossing.add_segment(1, 3);
  crossing.vertex_attribute_count = 1;
  crossing.vertex_attributes = {1, 2, 3, 4};
  EXPECT_THROW(tri::triangulate(crossing, tri::parse_switches("pq")), pdd::geometry_error);
}

TEST(Triangulate, JettisonKeepsEveryUsedVertex) {
  const pdd::pslg key = pdd::read_poly(pdd::test::bundled_data("key.poly"));
  const auto a = tri::triangulate(key, tri::parse_switches("pqa0.01"));
  const auto b = tri::triangulate(key, tri::parse_switches("pqa0.01j"));
  EXPECT_EQ(b.jettisoned_vertices, 0u); // key.poly has no isolated vertices
  EXPECT_EQ(a.mesh.vertices, b.mesh.vertices);
  // the helper itself: an unused vertex goes, the rest keep their order
  pdd::triangle_mesh m = a.mesh;
  m.vertices.insert(m.vertices.begin() + 3, pdd::point{9, 9});
  m.vertex_markers.insert(m.vertex_markers.begin() + 3, 5);
  for (auto& t : m.triangles)
    for (auto& v : t)
      v += v >= 3;
  for (auto& s : m.segments) {
    s.a += s.a >= 3;
    s.b += s.b >= 3;
  }
  EXPECT_EQ(tri::detail::jettison_unused_vertices(m), 1u);
  EXPECT_EQ(m.vertices, a.mesh.vertices);
  EXPECT_EQ(m.triangles, a.mesh.triangles);
  EXPECT_EQ(m.vertex_markers, a.mesh.vertex_markers);
}

TEST(FileNames, TriangleRules) {
  tri::switches s;
  auto f = tri::make_file_names("dir/key.poly", s);
  EXPECT_TRUE(s.poly);
  EXPECT_EQ(f.poly, "dir/key.poly");
  EXPECT_EQ(f.node, "dir/key.1.node");
  EXPECT_EQ(f.ele, "dir/key.1.ele");
  EXPECT_EQ(f.out_poly, "dir/key.1.poly");
  EXPECT_EQ(f.neigh, "");
  s = tri::parse_switches("pn");
  f = tri::make_file_names("key.1", s);
  EXPECT_EQ(f.poly, "key.1.poly");
  EXPECT_EQ(f.node, "key.2.node");
  EXPECT_EQ(f.neigh, "key.2.neigh");
  s = tri::parse_switches("p");
  EXPECT_EQ(tri::make_file_names("a.b/key.09.poly", s).ele, "a.b/key.10.ele");
  EXPECT_EQ(tri::make_file_names("v1.2x.poly", s).ele, "v1.2x.1.ele");
  EXPECT_EQ(tri::make_file_names("a.b/key", s).ele, "a.b/key.1.ele");
  s = tri::parse_switches("pNEP");
  f = tri::make_file_names("key.poly", s);
  EXPECT_EQ(f.node + f.ele + f.out_poly, "");
  s = tri::parse_switches("pI");
  f = tri::make_file_names("key.poly", s);
  EXPECT_EQ(f.node, "key.node");
  EXPECT_EQ(f.ele, "key.ele");
  EXPECT_EQ(f.out_poly, ""); // Triangle never overwrites the input .poly
  EXPECT_EQ(tri::make_file_names("key.poly", s, true).node, ""); // nor a .node it read
  s = {};
  EXPECT_EQ(tri::make_file_names("key.node", s).base, "key");
  EXPECT_FALSE(s.poly);
  EXPECT_EQ(tri::make_file_names("key.node", s).in_node, "key.node");
  EXPECT_EQ(tri::make_file_names("key", s).out_poly, ""); // no .poly without p or c
  s = tri::parse_switches("cev");
  f = tri::make_file_names("dir/pts.node", s);
  EXPECT_EQ(f.in_node + f.out_poly + f.edge, "dir/pts.nodedir/pts.1.polydir/pts.1.edge");
  EXPECT_EQ(f.v_node + f.v_edge, "dir/pts.1.v.nodedir/pts.1.v.edge");
  EXPECT_THROW(tri::make_file_names("key.1.ele", s), tri::switch_error);
  EXPECT_THROW(tri::make_file_names("key.1.area", s), tri::switch_error);
}

} // namespace triangulate_test
