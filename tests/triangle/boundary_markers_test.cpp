// pdd::triangle::triangulate's outputs beside the mesh: Triangle's boundary markers on every
// path, Triangle's empty mesh for a PSLG that encloses no domain, and switch C (pdd's verifier).
#include <pdd/errors.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/io/previous_mesh.hpp>
#include <pdd/triangle/triangulate.hpp>

#include <gtest/gtest.h>

#include "test_support.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace boundary_markers_test {
namespace tri = pdd::triangle;

namespace {

/// Triangle's box example, written out: the outer box's four corners (the last of marker 33),
/// only its left side a segment (marker 5), and a square hole whose segments have markers 0,
/// 0, 10, 0 (so without c no face is enclosed: Triangle's mesh is empty).
pdd::pslg triangle_box() {
  pdd::pslg g;
  for (const auto& [x, y, m] : std::vector<std::tuple<double, double, int>>{
           {0, 0, 0}, {0, 3, 0}, {3, 0, 0}, {3, 3, 33}, {1, 1, 0}, {1, 2, 0}, {2, 1, 0}, {2, 2, 0}})
    g.add_vertex({x, y}, m);
  g.add_segment(0, 1, 5);
  g.add_segment(4, 6, 0);
  g.add_segment(6, 7, 0);
  g.add_segment(7, 5, 10);
  g.add_segment(5, 4, 0);
  g.holes.push_back({1.5, 1.5});
  return g;
}

/// The box closed: all four sides segments (markers 5 left, 0 elsewhere), an internal segment
/// of marker 7 from the box's corner (3, 0) towards the hole, and the hole as above.
pdd::pslg closed_box() {
  pdd::pslg g = triangle_box();
  g.add_segment(1, 3, 0);
  g.add_segment(3, 2, 0);
  g.add_segment(2, 0, 0);
  g.add_vertex({2.5, 0.5}, 0);
  g.add_segment(2, 8, 7);
  return g;
}

double distance_to_segment(pdd::point p, pdd::point a, pdd::point b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double t = std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy), 0., 1.);
  return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

/// The vertices on an edge of exactly one triangle (the boundary of the triangulation).
std::vector<char> boundary_vertices(const pdd::triangle_mesh& m) {
  std::map<std::pair<pdd::index_t, pdd::index_t>, int> count;
  for (const auto& t : m.triangles)
    for (int i = 0; i < 3; ++i)
      ++count[std::minmax(t[i], t[(i + 1) % 3])];
  std::vector<char> out(m.vertices.size(), 0);
  for (const auto& [e, n] : count)
    if (n == 1) out[e.first] = out[e.second] = 1;
  return out;
}

/// Triangle's documented rule, decided from the geometry: the nonzero input marker, else the
/// nonzero marker of an input segment the vertex lies on (within 1e-12 of its length), else 1 on
/// the boundary, else 0. A vertex on two marked segments may take either marker.
void expect_triangles_vertex_markers(const pdd::triangle_mesh& m, const pdd::pslg& in,
                                     const std::string& what) {
  const std::vector<char> boundary = boundary_vertices(m);
  for (std::size_t v = 0; v < m.vertices.size(); ++v) {
    const int given = v < in.vertex_markers.size() ? in.vertex_markers[v] : 0;
    std::vector<int> allowed;
    if (given != 0) allowed.push_back(given);
    for (const pdd::segment& s : in.segments) {
      const pdd::point a = in.vertices[s.a], b = in.vertices[s.b];
      const double tolerance = 1e-12 * std::hypot(b.x - a.x, b.y - a.y);
      if (given == 0 && s.marker != 0 && distance_to_segment(m.vertices[v], a, b) <= tolerance)
        allowed.push_back(s.marker);
    }
    if (allowed.empty()) allowed.push_back(boundary[v] ? 1 : 0);
    EXPECT_NE(std::find(allowed.begin(), allowed.end(), m.vertex_markers[v]), allowed.end())
        << what << ": vertex " << v << " (" << m.vertices[v].x << ", " << m.vertices[v].y
        << ") has marker " << m.vertex_markers[v] << ", expected " << allowed.front();
  }
}

/// Every edge on a segment: its segment's nonzero marker, else 1 on the boundary, else 0.
void expect_triangles_segment_markers(const pdd::triangle_mesh& m, const pdd::pslg& in,
                                      const std::string& what) {
  std::map<std::pair<pdd::index_t, pdd::index_t>, int> count;
  for (const auto& t : m.triangles)
    for (int i = 0; i < 3; ++i)
      ++count[std::minmax(t[i], t[(i + 1) % 3])];
  for (const pdd::mesh_edge& e : m.segments) {
    const pdd::point mid{(m.vertices[e.a].x + m.vertices[e.b].x) / 2,
                         (m.vertices[e.a].y + m.vertices[e.b].y) / 2};
    int marker = 0;
    for (const pdd::segment& s : in.segments) {
      const pdd::point a = in.vertices[s.a], b = in.vertices[s.b];
      if (distance_to_segment(mid, a, b) <= 1e-12 * std::hypot(b.x - a.x, b.y - a.y))
        marker = s.marker;
    }
    if (marker == 0) marker = count[std::minmax(e.a, e.b)] == 1 ? 1 : 0;
    EXPECT_EQ(e.marker, marker) << what << ": edge " << e.a << "-" << e.b;
  }
}

} // namespace

TEST(BoundaryMarkers, TrianglesMarkersOnItsBoxExample) {
  // Triangle 1.6, triangle -pc box.poly: vertex markers 5 5 1 33 1 10 1 10 (the left side's 5
  // on its ends, the hole's marker 10 on 6 and 8, 1 on the hull's and the hole's other
  // vertices); its segments: the hull's 1 (the left side 5), the hole's 10 and 1.
  const tri::triangulation t = tri::triangulate(triangle_box(), tri::parse_switches("pc"));
  EXPECT_EQ(t.mesh.vertex_markers, (std::vector<int>{5, 5, 1, 33, 1, 10, 1, 10}));
  EXPECT_EQ(t.mesh.triangles.size(), 8u);
  std::vector<int> segment_markers;
  for (const pdd::mesh_edge& e : t.mesh.segments)
    segment_markers.push_back(e.marker);
  std::sort(segment_markers.begin(), segment_markers.end());
  EXPECT_EQ(segment_markers, (std::vector<int>{1, 1, 1, 1, 1, 1, 5, 10}));
}

TEST(BoundaryMarkers, FollowTrianglesRuleOnEveryPath) {
  const pdd::pslg box = closed_box();
  for (const char* switches : {"p", "pq", "pq30a0.01", "pqa0.05", "pqD", "pc", "pqa0.01e"}) {
    for (const std::size_t n : {std::size_t{1}, std::size_t{4}}) {
      const tri::triangulation t =
          tri::triangulate(box, tri::parse_switches(switches), {.threads = 2, .subdomains = n});
      const std::string what = std::string("-") + switches + " N " + std::to_string(n);
      expect_triangles_vertex_markers(t.mesh, box, what);
      expect_triangles_segment_markers(t.mesh, box, what);
    }
  }
}

TEST(BoundaryMarkers, FollowTrianglesRuleOnItsExamples) {
  const auto dir = pdd::test::shared_data_dir();
  if (dir.empty()) GTEST_SKIP() << "../shared/data absent";
  for (const char* name : {"triangle_face.poly", "triangle_A.poly", "guitar.poly"})
    for (const char* switches : {"p", "pq", "pq30", "pqa0.5"}) {
      const pdd::pslg d = pdd::read_poly(dir / name);
      const tri::triangulation t = tri::triangulate(d, tri::parse_switches(switches));
      const std::string what = std::string(name) + " -" + switches;
      expect_triangles_vertex_markers(t.mesh, d, what);
      expect_triangles_segment_markers(t.mesh, d, what);
    }
}

TEST(BoundaryMarkers, VertexSetsMarkTheirHull) {
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  pdd::pslg points;
  for (int i = 0; i < 300; ++i)
    points.add_vertex({u(rng), u(rng)}, i % 50 == 0 ? 9 : 0);
  for (const char* switches : {"", "q", "qa0.001", "c"}) {
    const tri::triangulation t = tri::triangulate(points, tri::parse_switches(switches));
    pdd::pslg unread = points; // without p Triangle reads no segment
    expect_triangles_vertex_markers(t.mesh, unread, std::string("-") + switches);
  }
}

TEST(EmptyDomain, TrianglesEmptyMeshWithTheReason) {
  // Triangle 1.6: triangle -p box.poly (and -pq, -pa0.1) writes 8 vertices (markers 5 5 0 33 0
  // 10 0 10) and no triangle: without c no face is enclosed by segments.
  for (const char* switches : {"p", "pq", "pqa0.1", "pqD", "pA", "pqe"}) {
    const tri::triangulation t = tri::triangulate(triangle_box(), tri::parse_switches(switches));
    EXPECT_TRUE(t.mesh.triangles.empty()) << switches;
    EXPECT_TRUE(t.mesh.segments.empty()) << switches;
    EXPECT_TRUE(t.edges.empty()) << switches;
    EXPECT_EQ(t.mesh.vertices.size(), 8u) << switches;
    EXPECT_EQ(t.mesh.vertex_markers, (std::vector<int>{5, 5, 0, 33, 0, 10, 0, 10})) << switches;
    EXPECT_NE(t.empty_domain.find("encloses no domain"), std::string::npos) << switches;
  }
  pdd::pslg no_segments;
  for (const pdd::point p : {pdd::point{0, 0}, {1, 0}, {0, 1}, {1, 1}})
    no_segments.add_vertex(p, 0);
  EXPECT_FALSE(tri::triangulate(no_segments, tri::parse_switches("pq")).empty_domain.empty());
  const tri::triangulation closed = tri::triangulate(closed_box(), tri::parse_switches("pq"));
  EXPECT_TRUE(closed.empty_domain.empty());
  EXPECT_FALSE(closed.mesh.triangles.empty());
  // pdd's own entry point still refuses it: generate meshes domains
  EXPECT_THROW((void)pdd::generate(triangle_box(), pdd::generate_options{}),
               pdd::empty_domain_error);
}

TEST(CheckSwitch, VerifiesEveryPath) {
  const pdd::pslg key = pdd::read_poly(pdd::test::bundled_data("key.poly"));
  for (const char* switches : {"pC", "pqC", "pq30a0.01C", "pqa0.01DC", "pcqC", "pqa0.01S50C"}) {
    const tri::triangulation t = tri::triangulate(key, tri::parse_switches(switches));
    ASSERT_TRUE(t.check.has_value()) << switches;
    EXPECT_TRUE(t.check->ok()) << switches << ": "
                               << (t.check->messages.empty() ? "" : t.check->messages.front());
  }
  EXPECT_FALSE(tri::triangulate(key, tri::parse_switches("pq")).check.has_value());
  pdd::pslg points;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int i = 0; i < 200; ++i)
    points.add_vertex({u(rng), u(rng)}, 0);
  points.add_vertex(points.vertices[7], 0); // an equal vertex: used by no triangle
  for (const char* switches : {"C", "qC", "qa0.001C"}) {
    const tri::triangulation t = tri::triangulate(points, tri::parse_switches(switches));
    ASSERT_TRUE(t.check.has_value()) << switches;
    EXPECT_TRUE(t.check->ok()) << switches;
  }
  EXPECT_FALSE(tri::triangulate(triangle_box(), tri::parse_switches("pC")).check.has_value())
      << "no triangle, nothing to check";
}

TEST(CheckSwitch, ReportsBoundsTheMeshDoesNotMeet) {
  // the check can fail: the same mesh against a smaller area and a larger angle
  const pdd::pslg key = pdd::read_poly(pdd::test::bundled_data("key.poly"));
  const tri::triangulation t = tri::triangulate(key, tri::parse_switches("pqa0.01C"));
  ASSERT_TRUE(t.check && t.check->ok());
  const pdd::verification_report small_area =
      tri::detail::check_mesh(t, &key, tri::parse_switches("pqa0.001"));
  EXPECT_FALSE(small_area.ok());
  EXPECT_GT(small_area.area_violations, 0u);
  const pdd::verification_report large_angle =
      tri::detail::check_mesh(t, &key, tri::parse_switches("pq34a0.01"));
  EXPECT_GT(large_angle.quality_violations, 0u);
}

TEST(CheckSwitch, RefinedMeshesAreChecked) {
  const pdd::pslg key = pdd::read_poly(pdd::test::bundled_data("key.poly"));
  const tri::triangulation first = tri::triangulate(key, tri::parse_switches("pqa0.1"));
  pdd::previous_mesh previous;
  previous.input.vertices = first.mesh.vertices;
  previous.input.vertex_markers = first.mesh.vertex_markers;
  previous.triangles = first.mesh.triangles;
  const tri::triangulation t = tri::refine(previous, tri::parse_switches("rqa0.01C"));
  ASSERT_TRUE(t.check.has_value());
  EXPECT_TRUE(t.check->ok()) << (t.check->messages.empty() ? "" : t.check->messages.front());
  expect_triangles_vertex_markers(t.mesh, previous.input, "-rqa0.01");
}

} // namespace boundary_markers_test
