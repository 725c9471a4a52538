// pdd::triangle::triangulate without p (vertex sets: the Delaunay triangulation, quality meshes
// of the convex hull), with c, e and v: properties checked with CGAL's exact predicates, and
// counts against Triangle 1.6 on the same vertices.
#include <pdd/core/kernel.hpp>
#include <pdd/mesh/quality.hpp>
#include <pdd/mesh/region_attributes.hpp>
#include <pdd/triangle/triangulate.hpp>

#include <CGAL/convex_hull_2.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace point_sets_test {
namespace tri = pdd::triangle;
using P2 = pdd::epick::Point_2;

namespace {

P2 p2(pdd::point p) {
  return {p.x, p.y};
}

/// n points of the R2 low-discrepancy sequence in the unit square (written with %.17g for
/// Triangle 1.6, the counts below are its counts on them).
pdd::pslg r2_points(std::size_t n) {
  pdd::pslg g;
  for (std::size_t i = 0; i < n; ++i)
    g.add_vertex({std::fmod(static_cast<double>(i) * 0.6180339887498949, 1.0),
                  std::fmod(static_cast<double>(i) * 0.7548776662466927, 1.0)});
  return g;
}

/// A 5 x 5 grid (every square's corners cocircular) and its centre twice.
pdd::pslg grid_with_duplicate() {
  pdd::pslg g;
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 5; ++x)
      g.add_vertex({x * 0.25, y * 0.25});
  g.add_vertex({0.5, 0.5}, 7); // equal to vertex 12
  return g;
}

double signed_area(const pdd::triangle_mesh& m, const std::array<pdd::index_t, 3>& t) {
  const pdd::point a = m.vertices[t[0]], b = m.vertices[t[1]], c = m.vertices[t[2]];
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

/// The area of the input's convex hull (CGAL's convex_hull_2, independent of pdd's hull).
double hull_area(const std::vector<pdd::point>& v) {
  std::vector<P2> pts, hull;
  for (const pdd::point p : v)
    pts.push_back(p2(p));
  CGAL::convex_hull_2(pts.begin(), pts.end(), std::back_inserter(hull));
  double a = 0.0;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const P2 &p = hull[i], &q = hull[(i + 1) % hull.size()];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * a;
}

/// Every triangle counter-clockwise, no mesh vertex strictly inside any triangle's circumcircle
/// (exact side_of_oriented_circle), the triangles' areas summing to the hull's area.
void expect_delaunay_of_hull(const pdd::triangle_mesh& m, const std::vector<pdd::point>& input) {
  double sum = 0.0;
  for (const auto& t : m.triangles) {
    const P2 a = p2(m.vertices[t[0]]), b = p2(m.vertices[t[1]]), c = p2(m.vertices[t[2]]);
    ASSERT_EQ(CGAL::orientation(a, b, c), CGAL::LEFT_TURN);
    for (const pdd::point v : m.vertices)
      ASSERT_NE(CGAL::side_of_oriented_circle(a, b, c, p2(v)), CGAL::ON_POSITIVE_SIDE)
          << pdd::to_string(v) << " inside the circumcircle";
    sum += signed_area(m, t);
  }
  const double hull = hull_area(input);
  EXPECT_NEAR(sum, hull, 1e-12 * hull);
}

/// Every input vertex kept first, at its input index, and used by a triangle (duplicates
/// excepted: no triangle uses them).
void expect_inputs_kept(const pdd::triangle_mesh& m, const pdd::pslg& in,
                        const std::set<pdd::index_t>& duplicates = {}) {
  std::vector<char> used(m.vertices.size(), 0);
  for (const auto& t : m.triangles)
    for (const pdd::index_t v : t)
      used[v] = 1;
  ASSERT_GE(m.vertices.size(), in.vertices.size());
  for (std::size_t i = 0; i < in.vertices.size(); ++i) {
    EXPECT_EQ(m.vertices[i], in.vertices[i]) << i;
    EXPECT_EQ(used[i] != 0, duplicates.count(static_cast<pdd::index_t>(i)) == 0) << i;
  }
}

/// Undirected edge -> number of triangles that have it.
std::map<std::pair<pdd::index_t, pdd::index_t>, int> edge_use(const pdd::triangle_mesh& m) {
  std::map<std::pair<pdd::index_t, pdd::index_t>, int> use;
  for (const auto& t : m.triangles)
    for (int i = 0; i < 3; ++i)
      ++use[std::minmax(t[i], t[(i + 1) % 3])];
  return use;
}

} // namespace

TEST(PointSets, DelaunayTriangulationAsTriangle) {
  const pdd::pslg in = r2_points(500);
  const tri::triangulation t = tri::triangulate(in, tri::parse_switches("Q"));
  expect_delaunay_of_hull(t.mesh, in.vertices);
  expect_inputs_kept(t.mesh, in);
  EXPECT_EQ(t.mesh.vertices.size(), 500u);  // no Steiner point
  EXPECT_EQ(t.mesh.triangles.size(), 987u); // Triangle 1.6: 987 triangles, 1486 edges
  EXPECT_TRUE(t.runs.empty());
  // hull vertices get marker 1, the others keep 0
  const auto use = edge_use(t.mesh);
  std::set<pdd::index_t> on_hull;
  for (const auto& [e, n] : use)
    if (n == 1) on_hull.insert({e.first, e.second});
  for (std::size_t i = 0; i < 500; ++i)
    EXPECT_EQ(t.mesh.vertex_markers[i], on_hull.count(static_cast<pdd::index_t>(i)) ? 1 : 0);
}

TEST(PointSets, CocircularGridAndDuplicates) {
  const pdd::pslg in = grid_with_duplicate();
  const tri::triangulation t = tri::triangulate(in, tri::parse_switches("c"));
  expect_delaunay_of_hull(t.mesh, in.vertices);
  expect_inputs_kept(t.mesh, in, {25});
  ASSERT_EQ(t.duplicate_vertices.size(), 1u);
  EXPECT_EQ(t.duplicate_vertices[0], (std::array<pdd::index_t, 2>{25, 12}));
  EXPECT_EQ(t.mesh.triangles.size(), 32u);
  // c: the hull's 16 edges (through the collinear vertices), counter-clockwise, marker 1
  ASSERT_EQ(t.mesh.segments.size(), 16u);
  for (const pdd::mesh_edge& s : t.mesh.segments) {
    EXPECT_EQ(s.marker, 1);
    const pdd::point a = t.mesh.vertices[s.a], b = t.mesh.vertices[s.b];
    EXPECT_EQ(CGAL::orientation(p2(a), p2(b), P2(0.5, 0.5)), CGAL::LEFT_TURN);
  }
  // j drops the duplicate, and only it
  const auto j = tri::triangulate(in, tri::parse_switches("j"));
  EXPECT_EQ(j.jettisoned_vertices, 1u);
  EXPECT_EQ(j.mesh.vertices.size(), 25u);
}

TEST(PointSets, QualityMeshOfTheHullKeepsEveryVertex) {
  const pdd::pslg in = r2_points(500);
  // Triangle 1.6 on the same vertices: q 1161, qa0.002 1241, q30a0.001 1912 triangles
  for (const auto& [sw, triangle_count] :
       {std::pair{"q", 1161.0}, std::pair{"qa0.002", 1241.0}, std::pair{"q30a0.001", 1912.0}}) {
    const auto s = tri::parse_switches(sw);
    const tri::triangulation t = tri::triangulate(in, s);
    expect_inputs_kept(t.mesh, in);
    expect_delaunay_of_hull(t.mesh, in.vertices); // a convex domain: Delaunay, not only CDT
    const pdd::mesh_statistics q = pdd::compute_statistics(t.mesh);
    if (s.max_area > 0) {
      EXPECT_LE(q.max_area, s.max_area) << sw;
    }
    EXPECT_GT(t.mesh.vertices.size(), in.vertices.size()) << sw; // refinement added vertices
    const auto n = static_cast<double>(t.mesh.triangles.size());
    EXPECT_LT(std::abs(n - triangle_count), 0.08 * triangle_count) << sw << ": " << n; // 1-5 % over
    EXPECT_EQ(t.runs.size(), 1u);
  }
}

TEST(PointSets, DuplicatesInAQualityMeshKeepTheirSlot) {
  const pdd::pslg in = grid_with_duplicate();
  const tri::triangulation t = tri::triangulate(in, tri::parse_switches("qa0.01"));
  expect_inputs_kept(t.mesh, in, {25});
  EXPECT_EQ(t.mesh.vertex_markers[25], 7);
  EXPECT_EQ(t.mesh.vertex_markers[12], 0);
  EXPECT_EQ(t.mesh.vertex_markers[0], 1); // a hull vertex
  EXPECT_LE(pdd::compute_statistics(t.mesh).max_area, 0.01);
  expect_delaunay_of_hull(t.mesh, in.vertices);
}

TEST(PointSets, FewerThanThreeOrCollinearAreRefused) {
  pdd::pslg two;
  two.add_vertex({0, 0});
  two.add_vertex({1, 0});
  two.add_vertex({1, 0});
  pdd::pslg line;
  for (int i = 0; i < 5; ++i)
    line.add_vertex({i * 1.0, i * 2.0});
  for (const char* sw : {"", "q", "c", "v"}) {
    try {
      (void)tri::triangulate(two, tri::parse_switches(sw));
      ADD_FAILURE() << "two distinct vertices accepted";
    } catch (const pdd::geometry_error& e) {
      EXPECT_NE(std::string(e.what()).find("at least three distinct vertices"), std::string::npos);
    }
    try {
      (void)tri::triangulate(line, tri::parse_switches(sw));
      ADD_FAILURE() << "collinear vertices accepted";
    } catch (const pdd::geometry_error& e) {
      EXPECT_NE(std::string(e.what()).find("collinear"), std::string::npos);
    }
  }
}

TEST(PointSets, ConvexHullOfAPslg) {
  // An L (area 3) with a square hole at (0.25, 0.25)-(0.75, 0.75); its hull has area 3.5.
  pdd::pslg l;
  l.add_loop(std::vector<pdd::point>{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, 3);
  l.add_loop(std::vector<pdd::point>{{0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75}, {0.25, 0.75}}, 4);
  l.holes.push_back({0.5, 0.5});
  const auto area = [](const pdd::triangle_mesh& m) {
    double a = 0.0;
    for (const auto& t : m.triangles)
      a += signed_area(m, t);
    return a;
  };
  const auto plain = tri::triangulate(l, tri::parse_switches("pqa0.05"));
  const auto hull = tri::triangulate(l, tri::parse_switches("pcqa0.05"));
  EXPECT_NEAR(area(plain.mesh), 3.0 - 0.25, 1e-12);
  EXPECT_NEAR(area(hull.mesh), 3.5 - 0.25, 1e-12); // the hull meshed, the hole carved
  expect_inputs_kept(hull.mesh, l);
  // the new hull edge (2,1)-(1,2) is a segment of marker 1; the L's own keep theirs
  std::map<int, std::size_t> by_marker;
  for (const pdd::mesh_edge& s : hull.mesh.segments)
    ++by_marker[s.marker];
  EXPECT_GT(by_marker[1], 0u);
  EXPECT_GT(by_marker[3], 0u);
  EXPECT_GT(by_marker[4], 0u);
  EXPECT_EQ(hull.mesh.vertex_markers[2], 3); // nonzero markers are kept
}

TEST(PointSets, EdgesAreTheTrianglesEdgesWithTriangleMarkers) {
  pdd::pslg sq;
  sq.add_loop(std::vector<pdd::point>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 5);
  sq.add_vertex({0.5, 0.5}); // an isolated vertex: edges of marker 0 around it
  for (const auto& [g, sw] : {std::pair{sq, "pqa0.01e"}, std::pair{r2_points(300), "e"}}) {
    const tri::triangulation t = tri::triangulate(g, tri::parse_switches(sw));
    const auto use = edge_use(t.mesh);
    ASSERT_EQ(t.edges.size(), use.size()) << sw; // each edge once
    std::set<std::pair<pdd::index_t, pdd::index_t>> seen;
    for (const pdd::mesh_edge& e : t.edges) {
      const auto k = std::minmax(e.a, e.b);
      ASSERT_TRUE(seen.insert(k).second) << sw;
      ASSERT_TRUE(use.count(k)) << sw;
      const bool boundary = use.at(k) == 1;
      // Triangle's rule: a segment's nonzero marker (5 on the square), else 1 on the boundary
      EXPECT_EQ(e.marker, boundary ? (g.segments.empty() ? 1 : 5) : 0) << sw;
    }
  }
}

TEST(PointSets, VoronoiIsTheDualOfTheDelaunayTriangulation) {
  const pdd::pslg in = r2_points(300);
  const tri::triangulation t = tri::triangulate(in, tri::parse_switches("v"));
  const auto& vd = t.voronoi;
  ASSERT_EQ(vd.vertices.size(), t.mesh.triangles.size());
  ASSERT_EQ(vd.edges.size(), t.edges.size());
  ASSERT_EQ(vd.directions.size(), t.edges.size());
  for (std::size_t i = 0; i < vd.vertices.size(); ++i) { // circumcentres: equidistant
    const auto& tr = t.mesh.triangles[i];
    const P2 c = p2(vd.vertices[i]);
    const double r = CGAL::squared_distance(c, p2(t.mesh.vertices[tr[0]]));
    for (int k = 1; k < 3; ++k)
      EXPECT_NEAR(CGAL::squared_distance(c, p2(t.mesh.vertices[tr[k]])), r, 1e-9 * r) << i;
  }
  std::size_t rays = 0;
  for (std::size_t e = 0; e < vd.edges.size(); ++e) {
    const pdd::mesh_edge d = t.edges[e];
    const P2 a = p2(t.mesh.vertices[d.a]), b = p2(t.mesh.vertices[d.b]);
    const auto& tr = t.mesh.triangles[static_cast<std::size_t>(vd.edges[e][0])];
    ASSERT_TRUE(std::count(tr.begin(), tr.end(), d.a) && std::count(tr.begin(), tr.end(), d.b));
    if (vd.edges[e][1] >= 0) { // both triangles have the Delaunay edge
      const auto& other = t.mesh.triangles[static_cast<std::size_t>(vd.edges[e][1])];
      EXPECT_TRUE(std::count(other.begin(), other.end(), d.a) &&
                  std::count(other.begin(), other.end(), d.b));
      EXPECT_EQ(vd.directions[e], pdd::point{});
      continue;
    }
    ++rays; // a ray: perpendicular to its hull edge (exactly), pointing away from the hull
    const pdd::point dir = vd.directions[e];
    EXPECT_EQ(dir.x * (b.x() - a.x()) + dir.y * (b.y() - a.y()), 0.0);
    EXPECT_EQ(CGAL::orientation(a, b, P2(a.x() + dir.x, a.y() + dir.y)), CGAL::RIGHT_TURN);
    EXPECT_EQ(d.marker, 1);
  }
  std::size_t boundary = 0;
  for (const auto& [k, n] : edge_use(t.mesh))
    boundary += n == 1;
  EXPECT_EQ(rays, boundary);
}

} // namespace point_sets_test
