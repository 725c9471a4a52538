// The straight-chord split's cut (madd/detail/chord_split.hpp): each hole goes to the child
// whose outer loop holds it, also when the hole touches the outer loop at a pinch vertex.
#include <pdd/madd/detail/chord_split.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace chord_split_test {

using pdd::point;
using pdd::detail::madd_loop;
using pdd::detail::madd_region;
using pdd::detail::madd_zvertex;

madd_loop loop_of(const std::vector<point>& pts) {
  madd_loop l;
  l.points = pts;
  l.markers.assign(pts.size(), 1);
  l.tags.assign(pts.size(), pdd::detail::madd_edge_tag{true, 0, 1});
  return l;
}

madd_zvertex end_on(point p, std::uint32_t edge) {
  madd_zvertex z;
  z.p = p;
  z.edge = edge;
  z.original = false;
  return z;
}

TEST(ChordSplit, AHoleTouchingTheOuterLoopGoesToTheChildThatHoldsIt) {
  // A 4 x 4 square with a triangular hole whose first vertex (2, 0) is a vertex of the outer
  // loop; the chord y = 1 from the left side to the right side leaves the hole in the first
  // child (the strip below it), whose outer loop passes through (2, 0).
  madd_region r;
  r.loops.push_back(loop_of({{0, 0}, {2, 0}, {4, 0}, {4, 4}, {0, 4}}));
  r.loops.push_back(loop_of({{2, 0}, {1.7, 0.4}, {2.3, 0.4}})); // clockwise
  r.area = pdd::detail::region_area(r);
  const auto ch = pdd::detail::chord_cut(r, end_on({0, 1}, 4), end_on({4, 1}, 2));
  ASSERT_EQ(ch[0].loops.size(), 2u);
  ASSERT_EQ(ch[1].loops.size(), 1u);
  EXPECT_NEAR(ch[0].area, 4.0 - 0.12, 1e-12);
  EXPECT_NEAR(ch[1].area, 12.0, 1e-12);
  EXPECT_NEAR(ch[0].area + ch[1].area, r.area, 1e-12);
  EXPECT_EQ(ch[0].loops[0].points.size(), 5u);       // (0, 1), (0, 0), (2, 0), (4, 0), (4, 1)
  EXPECT_FALSE(ch[0].loops[0].tags.back().external); // the chord
}

} // namespace chord_split_test
