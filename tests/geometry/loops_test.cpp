// Tests of pdd/geometry/loops.hpp: loop tracing, orientation, nesting, domain area.
#include "random_domains.hpp"
#include "test_support.hpp"

#include <pdd/geometry/loops.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>
#include <string>
#include <vector>

namespace loops_test {
namespace {

using pdd::index_t;
using pdd::point;

std::vector<point> square(double x0, double y0, double s, bool ccw = true) {
  std::vector<point> p{{x0, y0}, {x0 + s, y0}, {x0 + s, y0 + s}, {x0, y0 + s}};
  if (!ccw) std::reverse(p.begin(), p.end());
  return p;
}

TEST(Loops, SingleSquare) {
  pdd::pslg g;
  g.add_loop(square(0, 0, 2));
  const auto ls = pdd::find_loops(g);
  ASSERT_EQ(ls.loops.size(), 1u);
  const auto& l = ls.loops[0];
  EXPECT_EQ(l.vertices, (std::vector<index_t>{0, 1, 2, 3}));
  EXPECT_EQ(l.segments, (std::vector<index_t>{0, 1, 2, 3}));
  EXPECT_DOUBLE_EQ(l.signed_area, 4.0);
  EXPECT_TRUE(l.counterclockwise);
  EXPECT_EQ(l.depth, 0);
  EXPECT_EQ(l.parent, pdd::no_index);
  EXPECT_TRUE(l.bounds_domain_inside);
  EXPECT_TRUE(l.domain_on_left());
  EXPECT_DOUBLE_EQ(pdd::domain_area(g), 4.0);
}

TEST(Loops, TraversalStartsAtSmallestVertexAlongSmallerSegment) {
  pdd::pslg g;
  for (point p : square(0, 0, 1))
    g.add_vertex(p);
  // segments listed so that vertex 0's smaller segment goes to vertex 3 (clockwise)
  g.add_segment(3, 0);
  g.add_segment(1, 2);
  g.add_segment(0, 1);
  g.add_segment(2, 3);
  const auto ls = pdd::find_loops(g);
  ASSERT_EQ(ls.loops.size(), 1u);
  EXPECT_EQ(ls.loops[0].vertices, (std::vector<index_t>{0, 3, 2, 1}));
  EXPECT_EQ(ls.loops[0].segments, (std::vector<index_t>{0, 3, 1, 2}));
  EXPECT_DOUBLE_EQ(ls.loops[0].signed_area, -1.0);
  EXPECT_FALSE(ls.loops[0].counterclockwise);
  EXPECT_FALSE(ls.loops[0].domain_on_left());
}

TEST(Loops, NestedSquaresAlternate) {
  // squares of side 10, 8, 6, 4, 2 nested: domain = 100-64+36-16+4
  pdd::pslg g;
  for (int i = 0; i < 5; ++i)
    g.add_loop(square(i, i, 10 - 2 * i, i % 2 == 0));
  const auto ls = pdd::find_loops(g);
  ASSERT_EQ(ls.loops.size(), 5u);
  for (int i = 0; i < 5; ++i) {
    const auto& l = ls.loops[static_cast<std::size_t>(i)];
    EXPECT_EQ(l.depth, i);
    EXPECT_EQ(l.parent, i == 0 ? pdd::no_index : static_cast<index_t>(i - 1));
    EXPECT_EQ(l.bounds_domain_inside, i % 2 == 0);
    EXPECT_EQ(l.counterclockwise, i % 2 == 0);
    EXPECT_TRUE(l.domain_on_left());
  }
  EXPECT_DOUBLE_EQ(pdd::domain_area(g), 100.0 - 64 + 36 - 16 + 4);
}

TEST(Loops, DisjointOuterLoopsAndSiblingHoles) {
  pdd::pslg g;
  g.add_loop(square(0, 0, 10));
  g.add_loop(square(20, 0, 10));
  g.add_loop(square(1, 1, 2));
  g.add_loop(square(5, 5, 2));
  g.add_loop(square(21, 1, 3));
  const auto ls = pdd::find_loops(g);
  ASSERT_EQ(ls.loops.size(), 5u);
  const std::array<int, 5> depth{0, 0, 1, 1, 1};
  const std::array<index_t, 5> parent{pdd::no_index, pdd::no_index, 0, 0, 1};
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(ls.loops[i].depth, depth[i]) << i;
    EXPECT_EQ(ls.loops[i].parent, parent[i]) << i;
  }
  EXPECT_DOUBLE_EQ(pdd::domain_area(g), 200.0 - 4 - 4 - 9);
}

TEST(Loops, RandomDomainsWithHolesAndIslands) {
  int islands = 0, deep = 0;
  for (std::uint64_t seed = 1; seed <= 300; ++seed) {
    const auto d = pdd::test::random_domain(seed);
    const auto ls = pdd::find_loops(d.g);
    ASSERT_EQ(ls.loops.size(), d.loops.size()) << seed;
    double expected_area = 0;
    for (const auto& gl : d.loops)
      expected_area += (gl.depth % 2 == 0 ? 1 : -1) * std::abs(pdd::test::reference_area(gl.pts));
    std::vector<index_t> found_loop_of(d.loops.size(), pdd::no_index); // generated -> found
    for (std::size_t li = 0; li < ls.loops.size(); ++li) {
      const auto& l = ls.loops[li];
      const index_t gl = d.loop_of_vertex[l.vertices[0]];
      found_loop_of[gl] = static_cast<index_t>(li);
      ASSERT_EQ(l.vertices.size(), d.loops[gl].pts.size()) << seed;
      ASSERT_EQ(l.segments.size(), l.vertices.size());
      index_t smallest = l.vertices[0];
      for (std::size_t i = 0; i < l.vertices.size(); ++i) {
        smallest = std::min(smallest, l.vertices[i]);
        EXPECT_EQ(d.loop_of_vertex[l.vertices[i]], gl);
        const auto& s = d.g.segments[l.segments[i]];
        const index_t u = l.vertices[i], w = l.vertices[(i + 1) % l.vertices.size()];
        EXPECT_TRUE((s.a == u && s.b == w) || (s.a == w && s.b == u));
      }
      EXPECT_EQ(smallest, l.vertices[0]);
      std::vector<point> pts;
      for (index_t v : l.vertices)
        pts.push_back(d.g.vertices[v]);
      EXPECT_NEAR(l.signed_area, pdd::test::reference_area(pts), 1e-9);
      EXPECT_EQ(l.counterclockwise, l.signed_area > 0);
      EXPECT_EQ(l.depth, d.loops[gl].depth) << seed;
      EXPECT_EQ(l.bounds_domain_inside, d.loops[gl].depth % 2 == 0);
      if (l.depth == 2) ++islands;
      if (l.depth == 3) ++deep;
    }
    for (std::size_t li = 0; li < ls.loops.size(); ++li) {
      const auto& l = ls.loops[li];
      const int gp = d.loops[d.loop_of_vertex[l.vertices[0]]].parent;
      EXPECT_EQ(l.parent, gp < 0 ? pdd::no_index : found_loop_of[static_cast<std::size_t>(gp)]);
    }
    EXPECT_NEAR(pdd::domain_area(d.g), expected_area, 1e-9 * std::abs(expected_area)) << seed;
    EXPECT_NEAR(pdd::domain_area(ls), expected_area, 1e-9 * std::abs(expected_area));
  }
  EXPECT_GT(islands, 50); // the generator exercises deep nesting
  EXPECT_GT(deep, 10);
}

void expect_geometry_error(const pdd::pslg& g, const std::string& text,
                           const std::vector<std::size_t>& ids) {
  try {
    (void)pdd::find_loops(g);
    ADD_FAILURE() << "no exception; expected: " << text;
  } catch (const pdd::geometry_error& e) {
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    EXPECT_EQ(e.ids(), ids) << e.what();
  }
}

TEST(Loops, RejectsDanglingSegment) {
  pdd::pslg g;
  g.add_loop(square(0, 0, 4));
  const index_t a = g.add_vertex({1, 1}), b = g.add_vertex({2, 2});
  g.add_segment(a, b);
  expect_geometry_error(g,
                        "dangling segments and internal constraint segments are not supported "
                        "yet",
                        {4, 5});
  expect_geometry_error(g, "vertex 4 has 1 incident segment (segment 4)", {4, 5});
}

TEST(Loops, RejectsInternalConstraint) {
  pdd::pslg g;
  g.add_loop(square(0, 0, 4));
  g.add_segment(0, 2); // a diagonal: vertices 0 and 2 get degree 3
  expect_geometry_error(g, "vertex 0 has 3 incident segments (segments 0, 3, 4)", {0, 2});
}

TEST(Loops, RejectsIsolatedVertex) {
  pdd::pslg g;
  g.add_loop(square(0, 0, 4));
  g.add_vertex({1, 1});
  expect_geometry_error(g, "isolated vertices are not supported yet: vertex 4", {4});
}

TEST(Loops, RejectsDuplicateSegmentsAndVertices) {
  pdd::pslg g;
  g.add_vertex({0, 0});
  g.add_vertex({1, 0});
  g.add_segment(0, 1);
  g.add_segment(1, 0);
  expect_geometry_error(g, "segments 0, 1 join the same two vertices", {0, 1});
  pdd::pslg h;
  h.add_loop(square(0, 0, 1));
  h.add_loop(std::vector<point>{{0, 0}, {-1, 0}, {-1, -1}});
  expect_geometry_error(h, "duplicate vertices 0 and 4", {0, 4});
}

TEST(Loops, IntersectingSegmentsThrowGeometryError) {
  const std::vector<std::vector<std::vector<point>>> cases{
      {square(0, 0, 10), {{8, 4}, {12, 4}, {12, 6}, {8, 6}}}, // crossing
      {square(0, 0, 10), {{2, 0}, {4, 0}, {4, 2}, {2, 2}}},   // overlapping
      {square(0, 0, 10), {{5, 10}, {4, 8}, {6, 8}}},          // touching
      {{{0, 0}, {1, 0}, {2, 0}}},                             // collinear
      {{{0, 0}, {2, 0}, {2, 2}, {1, -1}}}};                   // bow tie
  for (const auto& c : cases) {
    pdd::pslg g;
    for (const auto& loop : c)
      g.add_loop(loop);
    EXPECT_THROW((void)pdd::find_loops(g), pdd::geometry_error);
  }
}

TEST(Loops, EmptyPslgHasNoLoops) {
  EXPECT_TRUE(pdd::find_loops(pdd::pslg{}).loops.empty());
  EXPECT_EQ(pdd::domain_area(pdd::pslg{}), 0.0);
}

} // namespace

} // namespace loops_test
