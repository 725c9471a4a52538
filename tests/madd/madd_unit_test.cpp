// Unit tests of the MADD steps on hand-made input: junction-triangle classification
// (Definition 4, Figures 3.3 and 3.5), the boundary discretisation and its triangulation
// (condition (ii)), the contracted graphs of both algorithms (Figures 3.5-3.9), separator
// insertion (Figure 3.10) and the edge-split registry that keeps neighbours conforming.
#include <pdd/madd/detail/assemble.hpp>
#include <pdd/madd/detail/graph.hpp>
#include <pdd/madd/detail/quotas.hpp>
#include <pdd/madd/detail/split.hpp>
#include <pdd/madd/detail/triangulation.hpp>
#include <pdd/partition/default_partitioner.hpp>

#include <test_support.hpp>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <numbers>
#include <random>
#include <set>
#include <vector>

namespace madd_unit_test {
namespace {

using pdd::point;
using namespace pdd::detail;

/// Boundary directions at p that are perpendicular to p -> q: the segment p q then forms 90
/// degree angles with the boundary at p.
std::array<point, 2> perpendicular_boundary(point p, point q) {
  const double dx = q.x - p.x, dy = q.y - p.y;
  return {point{p.x - dy, p.y + dx}, point{p.x + dy, p.y - dx}};
}

/// Boundary directions at p forming the angle `deg` with p -> q on one side (and 180 - deg
/// on the other): a straight boundary through p.
std::array<point, 2> tilted_boundary(point p, point q, double deg) {
  const double a = std::atan2(q.y - p.y, q.x - p.x) + deg * std::numbers::pi / 180.0;
  return {point{p.x + std::cos(a), p.y + std::sin(a)}, point{p.x - std::cos(a), p.y - std::sin(a)}};
}

std::array<std::array<point, 2>, 3> perpendicular_all(const std::array<point, 3>& p, point c) {
  return {perpendicular_boundary(p[0], c), perpendicular_boundary(p[1], c),
          perpendicular_boundary(p[2], c)};
}

madd_region polygon_region(const std::vector<std::vector<point>>& loops) {
  madd_region r;
  pdd::index_t seg = 0;
  for (const auto& pts : loops) {
    madd_loop l;
    for (const point& p : pts) {
      l.points.push_back(p);
      l.markers.push_back(1);
      l.tags.push_back(madd_edge_tag{true, seg++, 1});
    }
    r.loops.push_back(std::move(l));
  }
  r.area = region_area(r);
  return r;
}

const std::array<point, 3> equilateral{point{0, 0}, point{1, 0}, point{0.5, std::sqrt(3.0) / 2}};
const point equilateral_c{0.5, std::sqrt(3.0) / 6};

TEST(MaddJunction, EquilateralIsJunction) {
  const auto j = classify_triangle(equilateral, {false, false, false},
                                   perpendicular_all(equilateral, equilateral_c), 60.0);
  EXPECT_TRUE(j.contains_circumcentre);
  EXPECT_TRUE(j.junction);
  EXPECT_NEAR(j.c.x, equilateral_c.x, 1e-15);
  EXPECT_NEAR(j.c.y, equilateral_c.y, 1e-15);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(j.end_angle[k], 90.0, 1e-9);
    EXPECT_NEAR(j.central[k], 120.0, 1e-9);
    EXPECT_TRUE(j.pair_ok[k]);
  }
  EXPECT_EQ(j.best_pair, 0);
}

TEST(MaddJunction, ConditionOneObtuseAndRight) {
  // Figure 3.3: a2 a4 a5 does not include its circumcentre.
  const std::array<point, 3> obtuse{point{0, 0}, point{3, 0}, point{1.5, 0.4}};
  const std::array<std::array<point, 2>, 3> far{perpendicular_boundary(obtuse[0], {1.5, -1}),
                                                perpendicular_boundary(obtuse[1], {1.5, -1}),
                                                perpendicular_boundary(obtuse[2], {1.5, -1})};
  auto j = classify_triangle(obtuse, {false, false, false}, far, 60.0);
  EXPECT_FALSE(j.contains_circumcentre);
  EXPECT_FALSE(j.junction);
  // Exactly right-angled: the circumcentre is on the hypotenuse, not strictly inside.
  const std::array<point, 3> right{point{0, 0}, point{1, 0}, point{0, 1}};
  j = classify_triangle(right, {false, false, false}, far, 60.0);
  EXPECT_FALSE(j.contains_circumcentre);
  EXPECT_FALSE(j.junction);
}

TEST(MaddJunction, ConditionTwoBoundaryEdges) {
  // Figure 3.3: a1 a5 a6 has two edges on the boundary.
  const auto far = perpendicular_all(equilateral, equilateral_c);
  const auto one = classify_triangle(equilateral, {true, false, false}, far, 60.0);
  EXPECT_TRUE(one.junction);
  EXPECT_EQ(one.boundary_edges, 1);
  const auto two = classify_triangle(equilateral, {true, true, false}, far, 60.0);
  EXPECT_TRUE(two.contains_circumcentre);
  EXPECT_FALSE(two.junction);
  EXPECT_EQ(two.boundary_edges, 2);
}

TEST(MaddJunction, ConditionThreeAngles) {
  // Figure 3.5 case IV: c a3 forms a small angle theta with the boundary at a3, so the two
  // partial separators through c a3 are rejected and a1 c a2 is kept (it cuts off the
  // sub-triangle at edge a1 a2, which is pair 2 with a3 = vertex 2).
  auto far = perpendicular_all(equilateral, equilateral_c);
  far[2] = tilted_boundary(equilateral[2], equilateral_c, 40.0);
  auto j = classify_triangle(equilateral, {false, false, false}, far, 60.0);
  EXPECT_NEAR(j.end_angle[2], 40.0, 1e-9);
  EXPECT_TRUE(j.junction);
  EXPECT_FALSE(j.pair_ok[0]);
  EXPECT_FALSE(j.pair_ok[1]);
  EXPECT_TRUE(j.pair_ok[2]);
  EXPECT_EQ(j.best_pair, 2);
  // Figure 3.3: a1 a6 a7: the angles at two vertices are below Phi0, no partial separator.
  far[1] = tilted_boundary(equilateral[1], equilateral_c, 50.0);
  j = classify_triangle(equilateral, {false, false, false}, far, 60.0);
  EXPECT_TRUE(j.contains_circumcentre);
  EXPECT_FALSE(j.junction);
  EXPECT_EQ(j.best_pair, -1);
  // Max-min selection: all pairs acceptable, the one avoiding the weakest end wins.
  far = perpendicular_all(equilateral, equilateral_c);
  far[0] = tilted_boundary(equilateral[0], equilateral_c, 70.0);
  j = classify_triangle(equilateral, {false, false, false}, far, 60.0);
  EXPECT_EQ(j.best_pair, 0);
  // A sharp corner (< Phi0 / 2) makes the central angle of the opposite pair too small.
  const std::array<point, 3> sharp{point{0, 0}, point{1, -0.2}, point{1, 0.2}};
  const point c{0.52, 0.0};
  const auto jc =
      classify_triangle(sharp, {false, false, false}, perpendicular_all(sharp, c), 60.0);
  ASSERT_TRUE(jc.contains_circumcentre);
  EXPECT_LT(jc.central[0], 60.0);
  EXPECT_FALSE(jc.pair_ok[0]);
  EXPECT_TRUE(jc.junction);
  EXPECT_NE(jc.best_pair, 0);
}

TEST(MaddDiscretisation, CanonicalMidpointIsSymmetric) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1e3, 1e3);
  for (int i = 0; i < 1000; ++i) {
    const point a{u(rng), u(rng)}, b{u(rng), u(rng)};
    const point m1 = canonical_midpoint(a, b), m2 = canonical_midpoint(b, a);
    EXPECT_EQ(std::memcmp(&m1, &m2, sizeof(point)), 0);
  }
}

TEST(MaddDiscretisation, SquareRefinement) {
  const auto r = polygon_region({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}});
  const auto tr = triangulate_region(r, 0.25, 8);
  EXPECT_EQ(tr.z.size(), 16u);
  EXPECT_EQ(tr.encroachment_splits, 0u);
  double area = 0.0;
  for (const auto& f : tr.faces) {
    std::vector<point> p{tr.z[f.v[0]].p, tr.z[f.v[1]].p, tr.z[f.v[2]].p};
    EXPECT_GT(polygon_signed_area(p), 0.0);
    area += polygon_signed_area(p);
  }
  EXPECT_NEAR(area, 1.0, 1e-14);
  std::size_t boundary = 0;
  for (const auto& f : tr.faces)
    for (int k = 0; k < 3; ++k)
      boundary += f.nb[k] < 0 ? 1 : 0;
  EXPECT_EQ(boundary, tr.z.size());
}

TEST(MaddDiscretisation, EmptyDiametralCircles) {
  // A thin rectangle and a thin annulus: long pieces are encroached and must be bisected.
  const std::vector<madd_region> regions{
      polygon_region({{{0, 0}, {1, 0}, {1, 0.05}, {0, 0.05}}}), // corners only: not encroached
      polygon_region({{{0, 0}, {1, 0}, {1, 1}, {0, 1}},
                      {{0.03, 0.03}, {0.03, 0.97}, {0.97, 0.97}, {0.97, 0.03}}})};
  for (const auto& r : regions) {
    const auto tr = triangulate_region(r, 10.0, 12);
    if (r.loops.size() == 2) {
      EXPECT_GT(tr.encroachment_splits, 0u);
    }
    for (std::uint32_t u = 0; u < tr.z.size(); ++u) {
      const point a = tr.z[u].p, b = tr.z[tr.z[u].next].p;
      const point m{(a.x + b.x) / 2, (a.y + b.y) / 2};
      const double rad = distance(a, b) / 2;
      for (const auto& w : tr.z)
        EXPECT_GE(distance(w.p, m), rad * (1 - 1e-12)) << "piece " << u << " is encroached";
    }
    double area = 0.0;
    for (const auto& f : tr.faces)
      area += polygon_signed_area({tr.z[f.v[0]].p, tr.z[f.v[1]].p, tr.z[f.v[2]].p});
    EXPECT_NEAR(area, r.area, 1e-12);
  }
}

TEST(MaddDiscretisation, SharedEdgeGetsIdenticalPoints) {
  // The edge (1, 0.3)-(1.7, 1.9) in both orientations, refined to different depths: every
  // point of the coarser refinement is bitwise one of the finer one's.
  const auto a = polygon_region({{{0, 0}, {1, 0.3}, {1.7, 1.9}, {0, 1}}});
  const auto b = polygon_region({{{1, 0.3}, {3, 0}, {3, 2}, {1.7, 1.9}}});
  const auto ta = triangulate_region(a, 0.1, 0);
  const auto tb = triangulate_region(b, 0.4, 0);
  std::set<point> on_a;
  for (const auto& z : ta.z)
    if (!z.original && z.edge == 1) on_a.insert(z.p);
  std::size_t shared = 0;
  for (const auto& z : tb.z)
    if (!z.original && z.edge == 3) {
      EXPECT_TRUE(on_a.count(z.p)) << z.p.x << " " << z.p.y;
      ++shared;
    }
  EXPECT_EQ(on_a.size(), 31u);
  EXPECT_EQ(shared, 7u);
}

/// Edges minus nodes plus one of the contracted graph: its number of independent cycles.
long cycles(const madd_graph& g) {
  const auto pg = contracted_graph(g);
  return static_cast<long>(boost::num_edges(pg)) - static_cast<long>(boost::num_vertices(pg)) + 1;
}

TEST(MaddGraph, AlgorithmOneIsATreeOfJunctions) {
  // Figure 3.5: in a simply connected region every junction triangle gives one graph edge
  // and every edge separates, so G'_T is a tree with one more node than junctions.
  const auto r = polygon_region({{{0, 0}, {2, 0}, {2.2, 1}, {1, 1.6}, {-0.3, 1.1}}});
  const auto tr = triangulate_region(r, 0.2, 8);
  const auto g = build_madd_graph(tr, {.algorithm = 1});
  EXPECT_GT(g.junctions, 0u);
  EXPECT_EQ(g.nodes, g.junctions + 1);
  EXPECT_EQ(cycles(g), 0);
  for (const auto& f : g.faces) {
    if (f.tri == pdd::no_index) {
      EXPECT_FALSE(f.cuttable); // no Delaunay edge in algorithm 1
    }
    if (f.cuttable) {
      EXPECT_GE(f.min_angle, 60.0);
    }
  }
  double area = 0.0;
  for (const auto& c : g.cells)
    area += c.area;
  EXPECT_NEAR(area, r.area, 1e-12);
}

TEST(MaddGraph, AlgorithmTwoAcceptsGoodDelaunayEdges) {
  // Figures 3.8-3.9: Delaunay edges and circumcentre segments are candidates exactly when
  // their angles with the boundary are >= Phi0.
  const auto r = polygon_region({{{0, 0}, {2, 0}, {2.2, 1}, {1, 1.6}, {-0.3, 1.1}},
                                 {{0.8, 0.6}, {0.8, 0.9}, {1.2, 0.9}, {1.2, 0.6}}});
  const auto tr = triangulate_region(r, 0.2, 8);
  const auto g1 = build_madd_graph(tr, {.algorithm = 1});
  const auto g2 = build_madd_graph(tr, {.algorithm = 2});
  EXPECT_EQ(g1.junctions, g2.junctions);
  EXPECT_GE(g2.nodes, g1.nodes);
  // One hole: at most one independent cycle, plus (algorithm 2) one around every
  // circumcentre whose three segments may all be cut.
  EXPECT_LE(cycles(g1), 1);
  long around_c = 0;
  for (std::size_t t = 0; t < g2.info.size(); ++t) {
    int cuttable = 0;
    for (const auto& f : g2.faces)
      cuttable += f.tri == t && f.cuttable ? 1 : 0;
    around_c += cuttable == 3 ? 1 : 0;
  }
  EXPECT_LE(cycles(g2), 1 + around_c);
  std::size_t delaunay_cuttable = 0;
  for (const auto& f : g2.faces) {
    if (f.tri == pdd::no_index) {
      EXPECT_EQ(f.cuttable, f.min_angle >= 60.0) << f.min_angle;
      delaunay_cuttable += f.cuttable ? 1 : 0;
    } else if (f.cuttable) {
      EXPECT_GE(f.min_angle, 60.0);
    }
  }
  EXPECT_GT(delaunay_cuttable, 0u);
  // Every acceptable pair of circumcentre segments that stays cuttable meets at c at >= Phi0.
  for (std::size_t t = 0; t < g2.info.size(); ++t) {
    if (!g2.info[t].junction) continue;
    std::array<bool, 3> cut{};
    for (const auto& f : g2.faces)
      if (f.tri == t)
        for (int k = 0; k < 3; ++k)
          if (tr.faces[t].v[k] == f.z0) cut[k] = f.cuttable;
    for (int k = 0; k < 3; ++k)
      if (cut[(k + 1) % 3] && cut[(k + 2) % 3]) {
        EXPECT_GE(g2.info[t].central[k], 60.0);
      }
  }
}

TEST(MaddSplit, SeparatorInsertion) {
  // Figure 3.10: the cut graph edges become partial separators; the two children tile the
  // region, and every child vertex is a region vertex, a kept refinement vertex or a
  // circumcentre strictly inside the region.
  const auto r = polygon_region({{{0, 0}, {2, 0}, {2.2, 1}, {1, 1.6}, {-0.3, 1.1}}});
  for (const int alg : {1, 2}) {
    madd_split_options o;
    o.graph.algorithm = alg;
    o.graph.phi0_accept = 60.0 + 1e-7;
    o.target_length = 0.25;
    const auto res = split_region(r, o, pdd::default_partitioner{});
    ASSERT_TRUE(res.ok) << res.failure;
    EXPECT_NEAR(res.children[0].area + res.children[1].area, r.area, 1e-12);
    EXPECT_GT(res.children[0].area, 0.2 * r.area);
    EXPECT_GT(res.children[1].area, 0.2 * r.area);
    EXPECT_GE(res.min_angle, 60.0);
    std::set<point> region_vertices(r.loops[0].points.begin(), r.loops[0].points.end());
    std::set<point> kept;
    for (const auto& k : res.kept) {
      kept.insert(k.m);
      EXPECT_GT(k.t, 0.0);
      EXPECT_LT(k.t, 1.0);
      // On its edge, at its parameter.
      EXPECT_NEAR(k.m.x, k.lo.x + k.t * (k.hi.x - k.lo.x), 1e-12);
      EXPECT_NEAR(k.m.y, k.lo.y + k.t * (k.hi.y - k.lo.y), 1e-12);
    }
    std::size_t separator_edges = 0;
    for (const auto& child : res.children) {
      ASSERT_EQ(child.loops.size(), 1u);
      EXPECT_GT(polygon_signed_area(child.loops[0].points), 0.0);
      for (std::size_t i = 0; i < child.loops[0].size(); ++i) {
        const point p = child.loops[0].points[i];
        const bool on_boundary = region_vertices.count(p) || kept.count(p);
        if (!on_boundary) {
          EXPECT_EQ(child.loops[0].markers[i], 0); // a circumcentre
        }
        separator_edges += child.loops[0].tags[i].external ? 0 : 1;
      }
    }
    EXPECT_GT(separator_edges, 0u);
    EXPECT_EQ(separator_edges % 2, 0u); // each separator piece in both children
  }
}

TEST(MaddQuotas, ChildQuotasAndBalance) {
  using pdd::detail::child_quotas;
  using pdd::detail::split_balance;
  EXPECT_EQ(child_quotas(1.0, 2.0, 3), (std::array<std::size_t, 2>{1, 2}));
  EXPECT_EQ(child_quotas(2.0, 1.0, 3), (std::array<std::size_t, 2>{2, 1}));
  EXPECT_EQ(child_quotas(0.99, 0.01, 10), (std::array<std::size_t, 2>{9, 1}));
  EXPECT_EQ(child_quotas(0.01, 0.99, 10), (std::array<std::size_t, 2>{1, 9}));
  EXPECT_EQ(child_quotas(1.0, 1.0, 2), (std::array<std::size_t, 2>{1, 1}));
  EXPECT_DOUBLE_EQ(split_balance(0.6, 0.4, 2), 0.6);  // quota 2: the larger share
  EXPECT_DOUBLE_EQ(split_balance(0.6, 0.4, 0), 0.6);  // not into N: halves
  EXPECT_DOUBLE_EQ(split_balance(1.0, 2.0, 3), 0.5);  // a third and two thirds: exact
  EXPECT_DOUBLE_EQ(split_balance(1.5, 1.5, 3), 0.75); // halves of a region of three
  EXPECT_DOUBLE_EQ(pdd::detail::target_share(3), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(pdd::detail::target_share(8), 0.5);
  EXPECT_DOUBLE_EQ(pdd::detail::target_share(0), 0.5);
  // the quotas are the best: no other split of q lowers the larger area per subdomain
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> area(0.01, 1.0);
  for (int trial = 0; trial < 500; ++trial) {
    const double a0 = area(rng), a1 = area(rng);
    const std::size_t q = 2 + rng() % 40;
    const auto got = child_quotas(a0, a1, q);
    ASSERT_EQ(got[0] + got[1], q);
    const double worst = std::max(a0 / got[0], a1 / got[1]);
    for (std::size_t q0 = 1; q0 < q; ++q0)
      EXPECT_LE(worst, std::max(a0 / q0, a1 / (q - q0)) * (1 + 1e-15)) << trial;
  }
}

// allot_quotas minimises the largest area per subdomain (checked against exhaustive search
// on small cases); regions left out keep their quota.
TEST(MaddQuotas, AllotmentIsOptimal) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> area(0.05, 1.0);
  for (int trial = 0; trial < 300; ++trial) {
    const std::size_t n = 2 + rng() % 3, extra = rng() % 7;
    std::vector<double> areas(n);
    for (double& a : areas)
      a = area(rng);
    std::vector<std::size_t> quotas(n, 1), open;
    for (std::size_t i = 0; i < n; ++i)
      if (i != 0 || trial % 2) open.push_back(i); // region 0 is closed in even trials
    pdd::detail::allot_quotas(areas, quotas, open, extra);
    std::size_t sum = 0;
    double worst = 0.0;
    for (std::size_t i = 0; i < n; ++i)
      sum += quotas[i], worst = std::max(worst, areas[i] / quotas[i]);
    EXPECT_EQ(sum, n + extra);
    if (trial % 2 == 0) {
      EXPECT_EQ(quotas[0], 1u);
    }
    // exhaustive: every way of handing `extra` to the open regions
    double best = 1e300;
    std::vector<std::size_t> q(n, 1);
    const std::function<void(std::size_t, std::size_t)> search = [&](std::size_t k,
                                                                     std::size_t left) {
      if (k == open.size()) {
        if (left != 0) return;
        double w = 0.0;
        for (std::size_t i = 0; i < n; ++i)
          w = std::max(w, areas[i] / q[i]);
        best = std::min(best, w);
        return;
      }
      for (std::size_t give = 0; give <= left; ++give) {
        q[open[k]] = 1 + give;
        search(k + 1, left - give);
      }
      q[open[k]] = 1;
    };
    search(0, extra);
    EXPECT_DOUBLE_EQ(worst, best) << trial;
  }
}

TEST(MaddRegistry, NeighboursGetSplitVertices) {
  // Two unit squares share the edge x = 1. Separators of the left square end at y = 1/4
  // and y = 1/2 of it; the right square must get both vertices, in its own direction.
  std::vector<madd_region> regions{
      polygon_region({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}),
      polygon_region({{{1, 0}, {2, 0}, {2, 1}, {1, 1}}}),
  };
  for (auto& l : regions[1].loops[0].tags)
    l.external = false; // pretend: separator pieces
  const point lo{1, 0}, hi{1, 1};
  const point half = canonical_midpoint(lo, hi);
  const point quarter = canonical_midpoint(lo, half);
  apply_edge_splits(regions,
                    {{lo, hi, 0.5, half, 0}, {lo, hi, 0.25, quarter, 0}, {lo, hi, 0.5, half, 0}});
  const std::vector<point> left{{0, 0}, {1, 0}, quarter, half, {1, 1}, {0, 1}};
  const std::vector<point> right{{1, 0}, {2, 0}, {2, 1}, {1, 1}, half, quarter};
  EXPECT_EQ(regions[0].loops[0].points, left);
  EXPECT_EQ(regions[1].loops[0].points, right);
  EXPECT_EQ(regions[1].loops[0].tags.size(), 6u);
  EXPECT_FALSE(regions[1].loops[0].tags[4].external);
  // A region that has only a piece of the edge gets the vertices inside that piece.
  std::vector<madd_region> piece{polygon_region({{half, {1, 1}, {0.5, 1}}})};
  const point three_quarters = canonical_midpoint(half, hi);
  apply_edge_splits(piece, {{lo, hi, 0.75, three_quarters, 0}, {lo, hi, 0.5, half, 0}});
  const std::vector<point> expected{half, three_quarters, {1, 1}, {0.5, 1}};
  EXPECT_EQ(piece[0].loops[0].points, expected);
}

TEST(MaddRegistry, AssembleFindsInterfaces) {
  std::vector<madd_region> regions{
      polygon_region({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}),
      polygon_region({{{1, 0}, {2, 0}, {2, 1}, {1, 1}}}),
  };
  regions[0].loops[0].tags[1] = madd_edge_tag{};
  regions[1].loops[0].tags[3] = madd_edge_tag{};
  const auto d = assemble_decomposition(regions);
  ASSERT_EQ(d.subdomains.size(), 2u);
  ASSERT_EQ(d.interfaces.size(), 1u);
  EXPECT_EQ(d.interfaces[0].a, 0u);
  EXPECT_EQ(d.interfaces[0].b, 1u);
  ASSERT_EQ(d.interfaces[0].vertices.size(), 2u);
  EXPECT_EQ(d.vertices[d.interfaces[0].vertices[0]], (point{1, 0}));
  EXPECT_EQ(d.vertices.size(), 6u);
  int interface_tags = 0;
  for (std::size_t s = 0; s < 2; ++s)
    for (const auto& t : d.subdomains[s].tags[0])
      if (t.type == pdd::edge_tag::kind::interface) {
        ++interface_tags;
        EXPECT_EQ(t.id, 0u);
        EXPECT_EQ(t.neighbour, 1 - s);
      }
  EXPECT_EQ(interface_tags, 2);
}

} // namespace

} // namespace madd_unit_test
