// Tests of pdd/geometry/validate.hpp: each rejected geometry, and acceptance of valid ones.
#include "random_domains.hpp"
#include "test_support.hpp"

#include <pdd/core/kernel.hpp>
#include <pdd/geometry/validate.hpp>

#include <CGAL/intersections.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace validate_test {
namespace {

using pdd::index_t;
using pdd::point;

std::vector<point> square(double x0, double y0, double s) {
  return {{x0, y0}, {x0 + s, y0}, {x0 + s, y0 + s}, {x0, y0 + s}};
}

/// A 10x10 square with a 2x2 square hole at (4, 4) and its hole point.
pdd::pslg square_with_hole() {
  pdd::pslg g;
  g.add_loop(square(0, 0, 10));
  g.add_loop(square(4, 4, 2));
  g.holes.push_back({5, 5});
  return g;
}

/// Expects validate(g) to throw geometry_error whose message contains every text.
void expect_rejected(const pdd::pslg& g, const std::vector<std::string>& texts,
                     const std::vector<std::size_t>& ids) {
  try {
    pdd::validate(g);
    ADD_FAILURE() << "accepted; expected: " << texts.front();
  } catch (const pdd::geometry_error& e) {
    for (const auto& t : texts)
      EXPECT_NE(std::string(e.what()).find(t), std::string::npos)
          << "message: " << e.what() << "\nexpected to contain: " << t;
    EXPECT_EQ(e.ids(), ids) << e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "wrong exception type: " << e.what();
  }
}

TEST(Validate, AcceptsValidDomains) {
  EXPECT_NO_THROW(pdd::validate(square_with_hole()));
  for (std::uint64_t seed = 1; seed <= 100; ++seed)
    EXPECT_NO_THROW(pdd::validate(pdd::test::random_domain(seed).g)) << seed;
}

TEST(Validate, RejectsTooFewVertices) {
  pdd::pslg g;
  g.add_vertex({0, 0});
  g.add_vertex({1, 0});
  g.add_segment(0, 1);
  expect_rejected(g, {"at least 3 vertices", "has 2"}, {});
}

TEST(Validate, RejectsNonFiniteCoordinates) {
  auto g = square_with_hole();
  g.vertices[6].y = std::numeric_limits<double>::quiet_NaN();
  expect_rejected(g, {"vertex 6 has a non-finite coordinate"}, {6});
  g = square_with_hole();
  g.vertices[2].x = std::numeric_limits<double>::infinity();
  expect_rejected(g, {"vertex 2 has a non-finite coordinate"}, {2});
  g = square_with_hole();
  g.holes.push_back({0, -std::numeric_limits<double>::infinity()});
  expect_rejected(g, {"hole point 1 has a non-finite coordinate"}, {1});
}

TEST(Validate, RejectsSegmentIndexOutOfRange) {
  auto g = square_with_hole();
  g.add_segment(3, 42);
  expect_rejected(g, {"segment 8 refers to vertex 42", "only 8 vertices"}, {8});
}

TEST(Validate, RejectsZeroLengthSegment) {
  auto g = square_with_hole();
  g.add_segment(5, 5);
  expect_rejected(g, {"segment 8 has zero length", "vertex 5"}, {8});
}

TEST(Validate, RejectsDuplicateVertices) {
  auto g = square_with_hole();
  g.add_vertex({4, 6}); // same as vertex 7
  expect_rejected(g, {"duplicate vertices 7 and 8", "(4, 6)"}, {7, 8});
}

TEST(Validate, RejectsDuplicateSegments) {
  auto g = square_with_hole();
  g.add_segment(6, 5); // segment 5 joins 5 -> 6
  expect_rejected(g, {"duplicate segments 5 and 8", "vertices 5 and 6"}, {5, 8});
}

TEST(Validate, RejectsCrossingSegments) {
  pdd::pslg g;
  g.add_loop(square(0, 0, 10));
  // a hole loop poking out through the right side of the square
  g.add_loop(std::vector<point>{{8, 4}, {12, 4}, {12, 6}, {8, 6}});
  g.holes.push_back({9, 5});
  expect_rejected(g, {"segments cross", "segment 1 ", "segment 4 ", "1 more intersecting pair"},
                  {1, 4});
}

TEST(Validate, RejectsOverlappingSegments) {
  pdd::pslg g;
  g.add_loop(square(0, 0, 10));
  // a hole loop whose bottom edge runs along part of the square's bottom
  g.add_loop(std::vector<point>{{2, 0}, {4, 0}, {4, 2}, {2, 2}});
  g.holes.push_back({3, 1});
  expect_rejected(g, {"segments overlap", "segment 0 ", "segment 4 "}, {0, 4});
  // overlap of two segments sharing an endpoint (a spike going back along the edge)
  pdd::pslg h;
  for (point p : std::vector<point>{{0, 0}, {10, 0}, {5, 0}, {5, 5}})
    h.add_vertex(p);
  h.add_segment(0, 1);
  h.add_segment(1, 2);
  h.add_segment(2, 3);
  h.add_segment(3, 0);
  expect_rejected(h, {"segments overlap", "segment 0 ", "segment 1 "}, {0, 1});
}

TEST(Validate, RejectsVertexInSegmentInterior) {
  pdd::pslg g;
  g.add_loop(square(0, 0, 10));
  // a hole triangle with one corner on the square's top edge
  g.add_loop(std::vector<point>{{5, 10}, {4, 8}, {6, 8}});
  g.holes.push_back({5, 9});
  expect_rejected(g, {"vertex 4 (5, 10) lies in the interior of segment 2"}, {4, 2});
}

/// has_closed_loops, throwing on an invalid PSLG.
bool closed(const pdd::pslg& g) {
  return pdd::has_closed_loops(g);
}

TEST(Validate, AcceptsIsolatedVertex) {
  auto g = square_with_hole();
  EXPECT_TRUE(closed(g));
  g.add_vertex({1, 1});
  EXPECT_FALSE(closed(g));
  g.add_vertex({5.5, 5.5}); // in the hole: left out of the mesh, as Triangle does
  EXPECT_FALSE(closed(g));
}

TEST(Validate, AcceptsDanglingSegment) {
  auto g = square_with_hole();
  const index_t a = g.add_vertex({1, 1});
  g.add_segment(0, a); // from the corner into the domain
  EXPECT_FALSE(closed(g));
  const index_t b = g.add_vertex({2, 1}), c = g.add_vertex({3, 1});
  g.add_segment(b, c); // free in the face
  EXPECT_FALSE(closed(g));
}

TEST(Validate, AcceptsInternalConstraint) {
  auto g = square_with_hole();
  g.add_segment(0, 4); // corner of the square to corner of the hole: degree 3 at both
  EXPECT_FALSE(closed(g));
  // two faces split by a chord: each side is domain
  pdd::pslg h;
  h.add_loop(square(0, 0, 10));
  h.add_segment(0, 2);
  EXPECT_FALSE(closed(h));
  h.rule = pdd::domain_rule::triangle;
  EXPECT_NEAR(pdd::domain_area(h), 100.0, 1e-12);
}

TEST(Validate, AcceptsLoopsTouchingAtAPinchVertex) {
  pdd::pslg g;
  g.add_loop(square(0, 0, 10));
  // a triangular hole touching the outer loop at vertex 0 (the corner) and an island
  // touching the hole at one vertex
  const index_t a = g.add_vertex({4, 1}), b = g.add_vertex({1, 4});
  g.add_segment(0, a);
  g.add_segment(a, b);
  g.add_segment(b, 0);
  g.holes.push_back({1.5, 1.5});
  EXPECT_FALSE(closed(g));
  g.rule = pdd::domain_rule::triangle;
  EXPECT_NEAR(pdd::domain_area(g), 100.0 - 7.5, 1e-12);
}

TEST(Validate, NestedLoopWithoutHolePointIsAnInternalBoundary) {
  auto g = square_with_hole();
  g.holes.clear();
  EXPECT_FALSE(closed(g)); // both sides meshed: Triangle's rule
  g.rule = pdd::domain_rule::triangle;
  EXPECT_NEAR(pdd::domain_area(g), 100.0, 1e-12);
  g.rule = pdd::domain_rule::odd_nesting; // pdd's subdomains: the inner loop is a hole
  EXPECT_DOUBLE_EQ(pdd::domain_area(g), 96.0);
}

TEST(Validate, AllowsAnyPslgWithoutDomainCheck) {
  auto g = square_with_hole();
  g.holes.push_back({20, 5}); // outside: only checked with check_domain
  EXPECT_NO_THROW(pdd::validate(g, {.check_domain = false}));
  g.add_vertex({2, 3});
  g.add_vertex({2, 3}); // duplicates are still rejected
  EXPECT_THROW(pdd::validate(g, {.check_domain = false}), pdd::geometry_error);
}

TEST(Validate, RejectsAPslgWithoutDomain) {
  pdd::pslg g;
  g.add_vertex({0, 0});
  g.add_vertex({1, 0});
  g.add_vertex({0, 1});
  g.add_segment(0, 1); // no face is enclosed
  expect_rejected(g, {"the PSLG encloses no domain"}, {});
  g = square_with_hole();
  g.holes = {{1, 1}}; // eats the annulus; the inner square, without a hole point, stays domain
  EXPECT_FALSE(closed(g));
  g.holes = {{1, 1}, {5, 5}};
  expect_rejected(g, {"the PSLG encloses no domain"}, {});
}

TEST(Validate, RejectsHolePointOutsideEveryLoop) {
  auto g = square_with_hole();
  g.holes.push_back({20, 5});
  expect_rejected(g, {"hole point 1 (20, 5) lies outside the domain"}, {1});
}

TEST(Validate, HolePointInAnOddRegionEatsIt) {
  // Triangle's rule: a hole point removes its face wherever it lies
  auto g = square_with_hole();
  g.add_loop(std::vector<point>{{4.5, 4.5}, {5.5, 4.5}, {5, 5.5}});
  g.holes = {{4.2, 4.2}, {5, 5}}; // the island is a hole too
  EXPECT_FALSE(closed(g));
  g.holes = {{4.2, 4.2}};
  EXPECT_TRUE(closed(g));
}

TEST(Validate, RejectsHolePointOnASegment) {
  auto g = square_with_hole();
  g.holes = {{5, 4}};
  expect_rejected(g, {"hole point 0 (5, 4) lies on the segment between vertices 4 and 5"}, {0});
  g.holes = {{6, 6}};
  expect_rejected(g, {"hole point 0 (6, 6) lies on vertex 6"}, {0});
}

TEST(Validate, HoleRegionWithoutHolePointIsMeshed) {
  // the island's hole without its own hole point is an internal boundary
  auto g = square_with_hole();
  g.add_loop(std::vector<point>{{4.5, 4.5}, {5.5, 4.5}, {5.5, 5.5}, {4.5, 5.5}});
  g.add_loop(std::vector<point>{{4.8, 4.8}, {5.2, 4.8}, {5, 5.2}});
  g.holes = {{4.2, 4.2}};
  EXPECT_FALSE(closed(g));
  g.holes.push_back({5, 5});
  EXPECT_TRUE(closed(g));
}

/// O(S^2) reference: does any pair of segments meet other than at one shared endpoint at an
/// angle?
bool brute_force_clash(const pdd::pslg& g) {
  using K = pdd::epick;
  auto pt = [&](index_t v) { return K::Point_2(g.vertices[v].x, g.vertices[v].y); };
  for (std::size_t i = 0; i < g.segments.size(); ++i)
    for (std::size_t j = i + 1; j < g.segments.size(); ++j) {
      const auto &s = g.segments[i], &t = g.segments[j];
      const K::Segment_2 si(pt(s.a), pt(s.b)), sj(pt(t.a), pt(t.b));
      const int shared = (s.a == t.a) + (s.a == t.b) + (s.b == t.a) + (s.b == t.b);
      if (shared == 0 && CGAL::do_intersect(si, sj)) return true;
      if (shared == 1) { // meeting elsewhere than at the shared vertex means overlap
        const auto x = CGAL::intersection(si, sj);
        if (x && boost::get<K::Segment_2>(&*x)) return true;
      }
    }
  return false;
}

TEST(Validate, IntersectionsAgreeWithBruteForceOnPerturbedDomains) {
  int clashes = 0;
  for (std::uint64_t seed = 1; seed <= 300; ++seed) {
    auto d = pdd::test::random_domain(seed, 2, 0.8);
    std::mt19937_64 rng(seed);
    // move one vertex: sometimes far (crossings), sometimes onto another vertex's segment
    const std::size_t v = rng() % d.g.vertices.size();
    if (seed % 3 == 0) {
      const auto& s = d.g.segments[rng() % d.g.segments.size()];
      const point a = d.g.vertices[s.a], b = d.g.vertices[s.b];
      d.g.vertices[v] = {0.5 * a.x + 0.5 * b.x, 0.5 * a.y + 0.5 * b.y}; // midpoint, rounded
    } else {
      d.g.vertices[v].x += pdd::test::uniform(rng, -3, 3);
      d.g.vertices[v].y += pdd::test::uniform(rng, -3, 3);
    }
    const bool expected = brute_force_clash(d.g);
    clashes += expected;
    try {
      pdd::validate(d.g);
      EXPECT_FALSE(expected) << "seed " << seed << " accepted";
    } catch (const pdd::geometry_error& e) {
      const std::string m = e.what();
      const bool intersection = m.find("segments cross") != std::string::npos ||
                                m.find("segments overlap") != std::string::npos ||
                                m.find("lies in the interior of segment") != std::string::npos;
      EXPECT_EQ(intersection, expected) << "seed " << seed << ": " << m;
    }
  }
  EXPECT_GT(clashes, 50);
  EXPECT_LT(clashes, 280);
}

TEST(Validate, IntersectionCheckScalesToManySegments) {
  // a 200x200 grid of square holes: 160k segments; a quadratic pair test would take minutes
  pdd::pslg g;
  const int n = 200;
  g.add_loop(square(-1, -1, 2.0 * n + 1));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      g.add_loop(square(2.0 * i, 2.0 * j, 1));
      g.holes.push_back({2.0 * i + 0.5, 2.0 * j + 0.5});
    }
  EXPECT_NO_THROW(pdd::validate(g));
  g.add_loop(std::vector<point>{{150.5, 150.5}, {151.5, 150.25}, {151.5, 150.75}});
  g.holes.push_back({151.25, 150.5});
  expect_rejected(g, {"segments cross"}, {4 * (75 * n + 75 + 1) + 1, 4 * (n * n + 1)});
}

} // namespace

} // namespace validate_test
