// Triangle's vertex-set input and its -e / -v outputs: pdd::read_node, pdd::write_edge and
// pdd::write_voronoi, byte for byte in Triangle's layout.
#include "test_files.hpp"

#include <pdd/errors.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/io/triangle_files.hpp>

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

namespace triangle_edge_files_test {

TEST(TriangleEdgeFiles, ReadNodeKeepsMarkersAndAttributes) {
  const auto dir = pdd::test::fresh_dir("io_read_node");
  pdd::test::write_text(dir / "a.node", "# a comment\n3 2 1 1\n0 0 0 5 1\n1 1 0 6 0\n"
                                        "2 0 1 7 2\n# anything after the vertices is ignored\nx\n");
  const pdd::pslg g = pdd::read_node(dir / "a.node");
  ASSERT_EQ(g.vertices.size(), 3u);
  EXPECT_EQ(g.vertices[2], (pdd::point{0, 1}));
  EXPECT_EQ(g.vertex_markers, (std::vector<int>{1, 0, 2}));
  EXPECT_EQ(g.vertex_attribute_count, 1u);
  EXPECT_EQ(g.vertex_attributes, (std::vector<double>{5, 6, 7}));
  EXPECT_TRUE(g.segments.empty() && g.holes.empty() && g.regions.empty());
  pdd::test::write_text(dir / "bad.node", "3 2 0 0\n1 0 0\n2 1 nan\n3 0 1\n");
  try {
    (void)pdd::read_node(dir / "bad.node");
    FAIL() << "a NaN coordinate accepted";
  } catch (const pdd::input_error& e) {
    EXPECT_NE(std::string(e.what()).find("bad.node:3"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)pdd::read_node(dir / "missing.node"), pdd::error);
}

TEST(TriangleEdgeFiles, EdgeFileWithAndWithoutMarkers) {
  const auto dir = pdd::test::fresh_dir("io_edge");
  const std::vector<pdd::mesh_edge> edges{{0, 1, 1}, {1, 2, 0}, {2, 0, 7}};
  pdd::write_edge(dir / "m.edge", edges);
  EXPECT_EQ(pdd::test::read_text(dir / "m.edge"), "3 1\n1 1 2 1\n2 2 3 0\n3 3 1 7\n");
  pdd::write_edge(dir / "z.edge", edges, {.first_index = 0, .markers = false});
  EXPECT_EQ(pdd::test::read_text(dir / "z.edge"), "3 0\n0 0 1\n1 1 2\n2 2 0\n");
}

TEST(TriangleEdgeFiles, VoronoiFilesWithRays) {
  const auto dir = pdd::test::fresh_dir("io_voronoi");
  const std::vector<pdd::point> vertices{{0, 0.5}, {0.5, 0.25}};
  const std::vector<std::array<long long, 2>> edges{{0, 1}, {1, -1}};
  const std::vector<pdd::point> directions{{0, 0}, {-1, 0.5}};
  pdd::write_voronoi(dir / "m.v.node", dir / "m.v.edge", vertices, edges, directions);
  EXPECT_EQ(pdd::test::read_text(dir / "m.v.node"), "2 2 0 0\n1 0 0.5\n2 0.5 0.25\n");
  EXPECT_EQ(pdd::test::read_text(dir / "m.v.edge"), "2 0\n1 1 2\n2 2 -1 -1 0.5\n");
  pdd::write_voronoi(dir / "z.v.node", dir / "z.v.edge", vertices, edges, directions,
                     {.first_index = 0});
  EXPECT_EQ(pdd::test::read_text(dir / "z.v.edge"), "2 0\n0 0 1\n1 1 -1 -1 0.5\n");
  EXPECT_THROW(pdd::write_voronoi(dir / "x.v.node", dir / "x.v.edge", vertices, edges, {}),
               pdd::error);
}

} // namespace triangle_edge_files_test
