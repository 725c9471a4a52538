// Tests of pdd/geometry/lfs.hpp against an O(n^3) brute-force reference of Definition 7.
#include "random_domains.hpp"
#include "test_support.hpp"

#include <pdd/core/kernel.hpp>
#include <pdd/geometry/lfs.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace lfs_test {
namespace {

using pdd::index_t;
using pdd::point;
using K = pdd::epick;
using P = K::Point_2;

P cg(point p) {
  return {p.x, p.y};
}

/// Brute-force Definition 7: every vertex pair and every (vertex, non-incident segment) pair
/// whose connecting straight segment lies in the closed domain (checked against every
/// segment: no proper crossing, and the pieces between vertices touched have their
/// midpoints in the closed domain by ray-crossing parity).
struct brute_force {
  const pdd::pslg& g;

  index_t vertex_at(const P& p) const {
    for (std::size_t i = 0; i < g.vertices.size(); ++i)
      if (cg(g.vertices[i]) == p) return static_cast<index_t>(i);
    return pdd::no_index;
  }
  bool is_segment(index_t u, index_t v) const {
    if (u == pdd::no_index || v == pdd::no_index) return false;
    for (const auto& s : g.segments)
      if ((s.a == u && s.b == v) || (s.a == v && s.b == u)) return true;
    return false;
  }
  bool on_boundary(const P& p) const {
    for (const auto& s : g.segments) {
      const P a = cg(g.vertices[s.a]), b = cg(g.vertices[s.b]);
      if (CGAL::collinear(a, b, p) && CGAL::collinear_are_ordered_along_line(a, p, b)) return true;
    }
    return false;
  }
  bool in_closed_domain(const P& p) const {
    if (on_boundary(p)) return true;
    int crossings = 0;
    for (const auto& s : g.segments) {
      P lo = cg(g.vertices[s.a]), hi = cg(g.vertices[s.b]);
      if ((lo.y() > p.y()) == (hi.y() > p.y())) continue;
      if (lo.y() > hi.y()) std::swap(lo, hi);
      if (CGAL::orientation(lo, hi, p) == CGAL::LEFT_TURN) ++crossings;
    }
    return crossings % 2 == 1;
  }
  /// Segment pq in the closed domain; segment `skip` (the one q lies on) is not tested for a
  /// crossing since the rounded foot q may lie a hair beyond it.
  bool segment_in_domain(const P& p, const P& q, index_t skip = pdd::no_index) const {
    for (std::size_t i = 0; i < g.segments.size(); ++i) {
      if (i == skip) continue;
      const P a = cg(g.vertices[g.segments[i].a]), b = cg(g.vertices[g.segments[i].b]);
      const auto o1 = CGAL::orientation(a, b, p), o2 = CGAL::orientation(a, b, q);
      const auto o3 = CGAL::orientation(p, q, a), o4 = CGAL::orientation(p, q, b);
      if (o1 * o2 < 0 && o3 * o4 < 0) return false;
    }
    // pieces between the vertices on pq: (parameter, vertex id or no_index)
    std::vector<std::pair<double, index_t>> ts{{0.0, vertex_at(p)}, {1.0, vertex_at(q)}};
    const double dx = q.x() - p.x(), dy = q.y() - p.y();
    for (std::size_t i = 0; i < g.vertices.size(); ++i) {
      const P wp = cg(g.vertices[i]);
      if (CGAL::collinear(p, q, wp) && CGAL::collinear_are_strictly_ordered_along_line(p, wp, q))
        ts.emplace_back(((wp.x() - p.x()) * dx + (wp.y() - p.y()) * dy) / (dx * dx + dy * dy),
                        static_cast<index_t>(i));
    }
    std::sort(ts.begin(), ts.end());
    for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
      if (is_segment(ts[i].second, ts[i + 1].second)) continue; // on the boundary
      const double t = 0.5 * (ts[i].first + ts[i + 1].first);
      if (!in_closed_domain({p.x() + t * dx, p.y() + t * dy})) return false;
    }
    return true;
  }
  /// Definition 7 when `restricted`, Definition 1 (no domain condition) otherwise.
  double lfs(bool restricted = true) const {
    double best = std::numeric_limits<double>::infinity();
    const std::size_t n = g.vertices.size();
    for (std::size_t u = 0; u < n; ++u)
      for (std::size_t v = u + 1; v < n; ++v) {
        const P a = cg(g.vertices[u]), b = cg(g.vertices[v]);
        const double d = std::sqrt(CGAL::squared_distance(a, b));
        if (d < best && (!restricted || segment_in_domain(a, b))) best = d;
      }
    for (std::size_t v = 0; v < n; ++v)
      for (std::size_t s = 0; s < g.segments.size(); ++s) {
        const auto& sg = g.segments[s];
        if (sg.a == v || sg.b == v) continue;
        const P p = cg(g.vertices[v]), a = cg(g.vertices[sg.a]), b = cg(g.vertices[sg.b]);
        if (CGAL::angle(p, a, b) != CGAL::ACUTE || CGAL::angle(p, b, a) != CGAL::ACUTE) continue;
        const double ux = b.x() - a.x(), uy = b.y() - a.y();
        const double d =
            std::abs(ux * (p.y() - a.y()) - uy * (p.x() - a.x())) / std::sqrt(ux * ux + uy * uy);
        if (d >= best) continue;
        const double t = ((p.x() - a.x()) * ux + (p.y() - a.y()) * uy) / (ux * ux + uy * uy);
        if (!restricted ||
            segment_in_domain(p, {a.x() + t * ux, a.y() + t * uy}, static_cast<index_t>(s)))
          best = d;
      }
    return best;
  }
};

pdd::pslg loop_pslg(const std::vector<point>& outer) {
  pdd::pslg g;
  g.add_loop(outer);
  return g;
}

TEST(Lfs, ThinRectangle) {
  const auto g = loop_pslg({{0, 0}, {10, 0}, {10, 0.125}, {0, 0.125}});
  EXPECT_EQ(pdd::lfs_min(g), 0.125);
}

TEST(Lfs, SquareWithSquareHole) {
  auto g = loop_pslg({{0, 0}, {10, 0}, {10, 10}, {0, 10}});
  g.add_loop(std::vector<point>{{0.5, 3}, {9.5, 3}, {9.5, 7}, {0.5, 7}});
  g.holes.push_back({5, 5});
  EXPECT_EQ(pdd::lfs_min(g), 0.5);
  EXPECT_EQ(brute_force{g}.lfs(), 0.5);
}

// Keyhole: a notch (outside the domain) only 0.1 wide at its mouth; the prongs are 0.5 wide.
std::vector<point> keyhole(double x0, double y0) {
  std::vector<point> p{{0, 0}, {3, 0}, {3, 5}, {1.55, 5}, {2.5, 1}, {0.5, 1}, {1.45, 5}, {0, 5}};
  for (point& q : p)
    q = {q.x + x0, q.y + y0};
  return p;
}

TEST(Lfs, ClosestPairOutsideTheDomainDoesNotCount) {
  const auto g = loop_pslg(keyhole(0, 0));
  EXPECT_EQ(pdd::lfs_min(g), 0.5);                    // vertex (2.5, 1) to the side x = 3
  EXPECT_NEAR(brute_force{g}.lfs(false), 0.1, 1e-12); // Definition 1 would give the notch
  EXPECT_EQ(brute_force{g}.lfs(), 0.5);
}

TEST(Lfs, ClosestPairAcrossTheDomainCounts) {
  // the same keyhole as a hole: its notch mouth is now domain, its prongs are not
  auto g = loop_pslg({{-3, -3}, {6, -3}, {6, 8}, {-3, 8}});
  g.add_loop(keyhole(0, 0));
  g.holes.push_back({0.25, 0.25});
  EXPECT_NEAR(pdd::lfs_min(g), 0.1, 1e-12);
  EXPECT_EQ(pdd::lfs_min(g), brute_force{g}.lfs());
  // two holes 0.1 apart
  auto h = loop_pslg({{0, 0}, {10, 0}, {10, 10}, {0, 10}});
  h.add_loop(std::vector<point>{{2, 2}, {4, 2}, {4, 8}, {2, 8}});
  h.add_loop(std::vector<point>{{4.125, 3}, {6, 3}, {6, 7}, {4.125, 7}});
  h.holes = {{3, 5}, {5, 5}};
  EXPECT_EQ(pdd::lfs_min(h), 0.125); // vertex (4.125, 3) to the segment x = 4
}

TEST(Lfs, ClosestPairAcrossAHoleDoesNotCount) {
  // a thin diamond hole, 0.1 across, 10 long, in a big box
  auto g = loop_pslg({{-10, -10}, {20, -10}, {20, 10}, {-10, 10}});
  g.add_loop(std::vector<point>{{0, 0}, {5, -0.05}, {10, 0}, {5, 0.05}});
  g.holes.push_back({5, 0});
  const double edge = std::sqrt(25.0 + 0.05 * 0.05);
  EXPECT_NEAR(pdd::lfs_min(g), edge, 1e-12);
  EXPECT_LT(brute_force{g}.lfs(false), 0.1 + 1e-12);
  EXPECT_EQ(pdd::lfs_min(g), brute_force{g}.lfs());
}

// A comb: teeth 1 wide at the top with V-shaped gaps between them that are 0.2 wide at the
// top (outside the domain).
TEST(Lfs, CombWithNarrowGaps) {
  std::vector<point> p{{0, 0}, {10 * 1.2 - 0.2, 0}};
  for (int k = 9; k >= 0; --k) {
    p.push_back({k * 1.2 + 1, 5});
    p.push_back({k * 1.2, 5});
    if (k > 0) p.push_back({k * 1.2 - 0.1, 1.5});
  }
  const auto g = loop_pslg(p);
  const double lfs = pdd::lfs_min(g);
  EXPECT_NEAR(lfs, 1.0, 1e-12);
  EXPECT_EQ(lfs, brute_force{g}.lfs());
  EXPECT_LT(brute_force{g}.lfs(false), 0.21);
}

/// A random comb: teeth of random width, V-shaped gaps of random width and depth (outside
/// the domain), small diamond holes in the base; coordinates jittered.
pdd::pslg random_comb(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto u = [&](double a, double b) { return pdd::test::uniform(rng, a, b); };
  const int teeth = 2 + static_cast<int>(rng() % 6);
  std::vector<double> left(static_cast<std::size_t>(teeth)), right(left.size()), apex(left.size());
  double x = 0, min_apex = 10;
  for (std::size_t k = 0; k < left.size(); ++k) {
    left[k] = x;
    right[k] = x + u(0.3, 1.5);
    x = right[k] + u(0.05, 1.5);
    apex[k] = u(0.8, 3.0);
    min_apex = std::min(min_apex, apex[k]);
  }
  const double width = right.back();
  auto j = [&](double v) { return v + u(-0.01, 0.01); };
  std::vector<point> p{{j(0), j(0)}, {j(width), j(0)}};
  for (std::size_t k = left.size(); k-- > 0;) {
    p.push_back({j(right[k]), j(5)});
    p.push_back({j(left[k]), j(5)});
    if (k > 0) p.push_back({j(0.5 * (right[k - 1] + left[k])), j(apex[k])});
  }
  pdd::pslg g;
  g.add_loop(p);
  const int holes = static_cast<int>(rng() % 3);
  const double slot = width / 2;
  for (int h = 0; h < holes; ++h) {
    const double cx = slot * (h + 0.5) + u(-0.1, 0.1) * slot, cy = 0.5 * min_apex;
    const double hw = u(0.05, 0.35) * slot, hh = u(0.1, 0.45) * min_apex;
    g.add_loop(std::vector<point>{{cx - hw, cy}, {cx, cy - hh}, {cx + hw, cy}, {cx, cy + hh}});
    g.holes.push_back({cx, cy});
  }
  return g;
}

/// A box with random thin diamond holes of random orientation (bounding boxes kept apart):
/// many minima are vertex-segment distances, and holes block each other's perpendiculars.
pdd::pslg random_diamonds(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto u = [&](double a, double b) { return pdd::test::uniform(rng, a, b); };
  auto g = loop_pslg({{0, 0}, {10, 0}, {10, 10}, {0, 10}});
  std::vector<std::array<double, 4>> boxes;
  const int want = 4 + static_cast<int>(rng() % 12);
  for (int tries = 0; tries < 400 && static_cast<int>(boxes.size()) < want; ++tries) {
    const double cx = u(0, 10), cy = u(0, 10), th = u(0, 3.14159), a = u(0.2, 2.5),
                 b = u(0.02, 0.5);
    const double c = std::cos(th), s = std::sin(th);
    const std::vector<point> q{{cx + a * c, cy + a * s},
                               {cx - b * s, cy + b * c},
                               {cx - a * c, cy - a * s},
                               {cx + b * s, cy - b * c}};
    std::array<double, 4> bb{1e9, 1e9, -1e9, -1e9};
    for (const point& v : q)
      bb = {std::min(bb[0], v.x), std::min(bb[1], v.y), std::max(bb[2], v.x), std::max(bb[3], v.y)};
    if (bb[0] < 0.02 || bb[1] < 0.02 || bb[2] > 9.98 || bb[3] > 9.98) continue;
    bool clash = false;
    for (const auto& o : boxes)
      clash = clash || !(bb[2] + 0.01 < o[0] || o[2] + 0.01 < bb[0] || bb[3] + 0.01 < o[1] ||
                         o[3] + 0.01 < bb[1]);
    if (clash) continue;
    boxes.push_back(bb);
    g.add_loop(q);
    g.holes.push_back({cx, cy});
  }
  return g;
}

/// True if the value is a vertex-vertex distance of g.
bool is_vertex_distance(const pdd::pslg& g, double d) {
  for (std::size_t u = 0; u < g.vertices.size(); ++u)
    for (std::size_t v = u + 1; v < g.vertices.size(); ++v)
      if (std::sqrt(CGAL::squared_distance(cg(g.vertices[u]), cg(g.vertices[v]))) == d) return true;
  return false;
}

TEST(Lfs, MatchesBruteForceOnRandomDiamondHoles) {
  int vertex_segment = 0, restricted_differs = 0;
  for (std::uint64_t seed = 1; seed <= 150; ++seed) {
    const auto g = random_diamonds(seed);
    const double ref = brute_force{g}.lfs();
    ASSERT_NEAR(pdd::lfs_min(g), ref, 1e-12 * ref) << "seed " << seed;
    if (!is_vertex_distance(g, ref)) ++vertex_segment;
    if (brute_force{g}.lfs(false) < ref) ++restricted_differs;
  }
  EXPECT_GT(vertex_segment, 30);
  EXPECT_GT(restricted_differs, 30);
}

TEST(Lfs, MatchesBruteForceOnRandomDomainsWithHoles) {
  int restricted_differs = 0;
  for (std::uint64_t seed = 1; seed <= 120; ++seed) {
    const auto d = pdd::test::random_domain(1000 + seed, 3, 0.5);
    const double ref = brute_force{d.g}.lfs();
    const double got = pdd::lfs_min(d.g);
    ASSERT_NEAR(got, ref, 1e-12 * ref) << "seed " << seed;
    if (brute_force{d.g}.lfs(false) < ref) ++restricted_differs;
  }
  for (std::uint64_t seed = 1; seed <= 120; ++seed) {
    const auto g = random_comb(seed);
    const double ref = brute_force{g}.lfs();
    const double got = pdd::lfs_min(g);
    ASSERT_NEAR(got, ref, 1e-12 * ref) << "comb seed " << seed;
    if (brute_force{g}.lfs(false) < ref) ++restricted_differs;
  }
  EXPECT_GT(restricted_differs, 20); // distances outside the domain are excluded
}

TEST(Lfs, EmptyPslgIsInfinite) {
  EXPECT_EQ(pdd::lfs_min(pdd::pslg{}), std::numeric_limits<double>::infinity());
}

} // namespace

} // namespace lfs_test
