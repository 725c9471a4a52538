// General PSLGs (Triangle's rule, issue 13): a layered domain with regional attributes
// (internal constraints, vertices of degree 3 and 4), holes that touch each other and the outer
// boundary at pinch vertices (sectors >= 60 deg, small sectors, random ones), a T-junction
// (brick wall) grid, a combined one (dangling crack, isolated well, internal boundary), and
// random arrangements with internal and dangling constraints and isolated vertices, and random
// maps (faces of a jittered grid by colour).
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/geometry/validate.hpp>
#include <pdd/io/poly.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <random>
#include <sstream>
#include <utility>
#include <vector>

namespace pdd::test {

/// A 10 x 6 rectangle in five layers: internal constraints y = 2 and y = 4 across it and
/// x = 5 from y = 0 to y = 4 ((5, 2) has degree 4, (5, 0), (5, 4), (0, 2), ... degree 3). One
/// region point per face: attributes 1..5, maximum areas `area` times 1, 2, 4, 2, 8.
inline pslg layered_domain(double area = 0.02) {
  pslg g;
  const std::vector<point> outer = {{0, 0},  {5, 0}, {10, 0}, {10, 2}, {10, 4},
                                    {10, 6}, {0, 6}, {0, 4},  {0, 2}};
  g.add_loop(outer, 1);                    // vertices 0..8
  const index_t m2 = g.add_vertex({5, 2}); // 9
  const index_t m4 = g.add_vertex({5, 4}); // 10
  for (const auto& [a, b] : std::vector<std::pair<index_t, index_t>>{
           {8, m2}, {m2, 3}, {7, m4}, {m4, 4}, {1, m2}, {m2, m4}})
    g.add_segment(a, b, 2);
  const double scale[] = {1, 2, 4, 2, 8};
  const point seeds[] = {{2.5, 1}, {7.5, 1}, {2.5, 3}, {7.5, 3}, {5, 5}};
  for (int r = 0; r < 5; ++r)
    g.regions.push_back({seeds[r], static_cast<double>(r + 1), area * scale[r]});
  g.rule = domain_rule::triangle;
  return g;
}

/// A 10 x 10 square with two diamond holes touching at the pinch vertex (5, 5) and a triangular
/// hole touching the bottom edge at (5, 0) (every angle at the pinch vertices >= 60 deg).
inline pslg pinched_rings() {
  pslg g;
  g.add_loop(std::vector<point>{{0, 0}, {5, 0}, {10, 0}, {10, 10}, {0, 10}}); // 0..4
  const index_t p = g.add_vertex({5, 5});                                     // 5
  const auto ring = [&](std::vector<point> others) {
    index_t prev = p;
    for (const point& q : others) {
      const index_t v = g.add_vertex(q);
      g.add_segment(prev, v);
      prev = v;
    }
    g.add_segment(prev, p);
  };
  ring({{3.5, 6.5}, {2, 5}, {3.5, 3.5}});
  ring({{6.5, 3.5}, {8, 5}, {6.5, 6.5}});
  const index_t a = g.add_vertex({6, 2}), b = g.add_vertex({4, 2});
  g.add_segment(1, a);
  g.add_segment(a, b);
  g.add_segment(b, 1);
  g.holes = {{3.5, 5}, {6.5, 5}, {5, 1.2}};
  g.rule = domain_rule::triangle;
  return g;
}

/// Adds a triangular hole (apex, apex + r at angles a1, a2 deg) touching the rest of g at its
/// apex, with its hole point at the centroid.
inline void add_wedge_hole(pslg& g, index_t apex, double a1, double a2, double r) {
  const point c = g.vertices[apex];
  const auto at = [&](double deg) {
    const double t = deg * std::numbers::pi / 180.0;
    return point{c.x + r * std::cos(t), c.y + r * std::sin(t)};
  };
  const point p = at(a1), q = at(a2);
  const index_t ip = g.add_vertex(p), iq = g.add_vertex(q);
  g.add_segment(apex, ip);
  g.add_segment(ip, iq);
  g.add_segment(iq, apex);
  g.holes.push_back({(c.x + p.x + q.x) / 3.0, (c.y + p.y + q.y) / 3.0});
}

/// A 10 x 10 square with small angles at its pinch vertices: a triangular hole touching the
/// bottom side at (5, 0) leaves sectors of 14 and 135 deg there; four triangular holes touching
/// at (5, 6) leave the face sectors of 20, 35, 50 and 75 deg between them.
inline pslg pinched_sectors() {
  pslg g;
  g.add_loop(std::vector<point>{{0, 0}, {5, 0}, {10, 0}, {10, 10}, {0, 10}});
  add_wedge_hole(g, 1, 14, 45, 1.5);
  const index_t p = g.add_vertex({5, 6});
  double at = 10;
  for (const double sector : {20.0, 35.0, 50.0, 75.0}) {
    add_wedge_hole(g, p, at, at + 45, 2);
    at += 45 + sector;
  }
  g.rule = domain_rule::triangle;
  return g;
}

/// A random domain of pinch vertices in a 10 x 10 square: up to two triangular holes touching
/// the bottom side at one vertex each, and one to three vertices inside where two to four
/// triangular holes touch; the face's sectors between them are random, down to about 2 deg, so
/// many fall below 60 deg. With crack_probability > 0, each sector between two holes at a
/// vertex inside gets, with that probability, a crack: a dangling segment from the pinch
/// vertex along the sector's bisector (the corner and the crack then form two small sectors
/// where the face's is below 120 deg). Valid by construction. Deterministic for a seed.
inline pslg random_pinched(std::uint32_t seed, double crack_probability = 0.0) {
  std::mt19937 rng(seed);
  const auto uniform = [&](double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
  };
  const auto count = [&](int lo, int hi) {
    return std::uniform_int_distribution<int>(lo, hi)(rng);
  };
  pslg g;
  std::vector<point> outer{{0, 0}};
  const int shore = count(0, 2);
  for (int k = 0; k < shore; ++k)
    outer.push_back({1.5 + 4.5 * k + uniform(0, 1.5), 0}); // wedges 0.6 apart at least
  for (const point q : {point{10, 0}, point{10, 10}, point{0, 10}})
    outer.push_back(q);
  g.add_loop(outer);
  for (int k = 0; k < shore; ++k) {
    const double a1 = uniform(5, 80);
    add_wedge_hole(g, static_cast<index_t>(k + 1), a1, a1 + uniform(10, 170 - a1),
                   uniform(0.6, 1.2));
  }
  const int inside = count(1, 3);
  for (int k = 0; k < inside; ++k) {
    const index_t p = g.add_vertex({1.8 + 3.2 * k, uniform(4, 8)});
    const int m = count(2, 4);
    std::vector<double> wedge(m), gap(m);
    double wedges = 0, weights = 0;
    for (int j = 0; j < m; ++j) {
      wedges += wedge[j] = uniform(3, 80);
      weights += gap[j] = uniform(0.2, 1);
    }
    double at = uniform(0, 360);
    const double r = uniform(0.5, 1.4);
    for (int j = 0; j < m; ++j) {
      add_wedge_hole(g, p, at, at + wedge[j], r);
      const double sector = (360 - wedges) * gap[j] / weights;
      if (crack_probability > 0.0 && uniform(0, 1) < crack_probability) {
        const double mid = (at + wedge[j] + sector / 2) * std::numbers::pi / 180;
        const point q = g.vertices[p];
        g.add_segment(p,
                      g.add_vertex({q.x + 0.7 * r * std::cos(mid), q.y + 0.7 * r * std::sin(mid)}));
      }
      at += wedge[j] + sector;
    }
  }
  g.rule = domain_rule::triangle;
  return g;
}

/// A 4 x 4 square as a brick wall: internal constraints y = 1, 2, 3 across it and vertical
/// ones between them at x = 1, 3 (odd rows) and x = 2 (even rows): T-junctions everywhere.
inline pslg t_junction_grid() {
  pslg g;
  std::vector<point> outer;
  for (int x = 0; x < 4; ++x)
    outer.push_back({static_cast<double>(x), 0});
  for (int y = 0; y < 4; ++y)
    outer.push_back({4, static_cast<double>(y)});
  for (int x = 4; x > 0; --x)
    outer.push_back({static_cast<double>(x), 4});
  for (int y = 4; y > 0; --y)
    outer.push_back({0, static_cast<double>(y)});
  g.add_loop(outer);
  const auto vertex = [&](double x, double y) {
    for (index_t v = 0; v < g.vertices.size(); ++v)
      if (g.vertices[v] == point{x, y}) return v;
    return g.add_vertex({x, y});
  };
  for (int y = 1; y <= 3; ++y)
    for (int x = 0; x < 4; ++x)
      g.add_segment(vertex(x, y), vertex(x + 1, y));
  for (int row = 0; row < 4; ++row) {
    const std::vector<double> xs =
        row % 2 == 0 ? std::vector<double>{1, 3} : std::vector<double>{2};
    for (const double x : xs)
      g.add_segment(vertex(x, row), vertex(x, row + 1));
  }
  g.rule = domain_rule::triangle;
  return g;
}

/// The layered domain plus a dangling crack in the bottom-left face, an isolated well in the
/// top face, and an internal boundary (a square loop without hole point) in the bottom-right
/// face; regions as layered_domain.
inline pslg combined_domain(double area = 0.02) {
  pslg g = layered_domain(area);
  g.add_segment(g.add_vertex({1, 0.5}), g.add_vertex({2, 1.5}), 3);
  g.add_vertex({7.5, 5}, 4);
  g.add_loop(std::vector<point>{{7, 0.5}, {8, 0.5}, {8, 1.5}, {7, 1.5}}, 5);
  return g;
}

/// True when segment (a, b) would meet a segment of g at a shared endpoint at less than
/// `min_deg` degrees (tinier input angles than double precision resolves make the kernel refuse
/// the domain with a meshing_error, see kernels/cgal/detail/mesher.hpp).
inline bool makes_small_angle(const pslg& g, index_t a, index_t b, double min_deg) {
  const auto angle = [&](index_t v, index_t p, index_t q) {
    const point &o = g.vertices[v], &x = g.vertices[p], &y = g.vertices[q];
    const double ux = x.x - o.x, uy = x.y - o.y, wx = y.x - o.x, wy = y.y - o.y;
    return std::abs(std::atan2(ux * wy - uy * wx, ux * wx + uy * wy)) * 180.0 / std::numbers::pi;
  };
  for (const segment& s : g.segments)
    for (const auto& [v, other] : {std::pair{a, b}, std::pair{b, a}}) {
      if (s.a != v && s.b != v) continue;
      if (angle(v, other, s.a == v ? s.b : s.a) < min_deg) return true;
    }
  return false;
}

/// A random arrangement in the unit square: the outer loop through two random points per side,
/// isolated vertices on a jittered 5 x 5 grid, then up to `tries` random segments between
/// vertices kept when the PSLG stays valid and no angle at a shared endpoint is below 10 deg
/// (internal constraints, dangling segments and chains, small angles down to 10 deg); the
/// vertices left on no segment stay isolated. Deterministic for a seed.
inline pslg random_arrangement(std::uint32_t seed, int tries = 14) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.2, 0.8), jitter(-0.06, 0.06);
  pslg g;
  std::vector<point> outer{{0, 0}};
  const double s0 = u(rng) * 0.5, s1 = 0.5 + u(rng) * 0.5;
  for (const double s : {s0, s1})
    outer.push_back({s, 0});
  outer.push_back({1, 0});
  for (const double s : {s0, s1})
    outer.push_back({1, s});
  outer.push_back({1, 1});
  for (const double s : {s1, s0})
    outer.push_back({s, 1});
  outer.push_back({0, 1});
  for (const double s : {s1, s0})
    outer.push_back({0, s});
  g.add_loop(outer);
  for (int i = 1; i < 5; ++i)
    for (int j = 1; j < 5; ++j)
      if (rng() % 3 != 0) g.add_vertex({i / 5.0 + jitter(rng), j / 5.0 + jitter(rng)});
  std::uniform_int_distribution<std::size_t> pick(0, g.vertices.size() - 1);
  for (int t = 0; t < tries; ++t) {
    const index_t a = static_cast<index_t>(pick(rng)), b = static_cast<index_t>(pick(rng));
    if (a == b || makes_small_angle(g, a, b, 10.0)) continue;
    pslg trial = g;
    trial.add_segment(a, b);
    try {
      validate(trial, {.check_domain = false});
    } catch (const geometry_error&) {
      continue; // crosses, overlaps or duplicates a segment
    }
    g = std::move(trial);
  }
  g.rule = domain_rule::triangle;
  return g;
}

/// A random map on an n x n grid of unit cells (interior grid vertices jittered by up to 0.3):
/// each cell takes the colour of the nearest of five random sites, colour 0 is a hole (a hole
/// point in each of its cells); the segments are the outer boundary and the grid edges
/// between cells of different colours (internal constraints, vertices of degree 2 to 4, no
/// dangling segment and no isolated vertex). Faces may touch themselves at a vertex and
/// corners may fall below 60 deg. Deterministic for a seed.
inline pslg random_map(std::uint32_t seed, int n = 6) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, n), jitter(-0.3, 0.3);
  std::vector<point> grid; // (n + 1)^2 corners, row by row
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const bool border = i == 0 || j == 0 || i == n || j == n;
      grid.push_back({i + (border ? 0.0 : jitter(rng)), j + (border ? 0.0 : jitter(rng))});
    }
  std::vector<point> sites(5);
  for (point& p : sites)
    p = {u(rng), u(rng)};
  std::vector<int> colour(static_cast<std::size_t>(n * n));
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const point c{i + 0.5, j + 0.5};
      int best = 0;
      for (int k = 1; k < 5; ++k)
        if (std::hypot(sites[k].x - c.x, sites[k].y - c.y) <
            std::hypot(sites[best].x - c.x, sites[best].y - c.y))
          best = k;
      colour[static_cast<std::size_t>(j * n + i)] = best;
    }
  const auto cell = [&](int i, int j) { // -1 outside the grid
    return i < 0 || j < 0 || i >= n || j >= n ? -1 : colour[static_cast<std::size_t>(j * n + i)];
  };
  pslg g;
  std::vector<index_t> id(grid.size(), no_index);
  const auto vertex = [&](int i, int j) {
    const auto k = static_cast<std::size_t>(j * (n + 1) + i);
    if (id[k] == no_index) id[k] = g.add_vertex(grid[k]);
    return id[k];
  };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      if (i < n && cell(i, j - 1) != cell(i, j)) g.add_segment(vertex(i, j), vertex(i + 1, j));
      if (j < n && cell(i - 1, j) != cell(i, j)) g.add_segment(vertex(i, j), vertex(i, j + 1));
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      if (cell(i, j) == 0) {
        const auto k = static_cast<std::size_t>(j * (n + 1) + i);
        const point a = grid[k], b = grid[k + 1], c = grid[k + n + 2], d = grid[k + n + 1];
        g.holes.push_back({(a.x + b.x + c.x + d.x) / 4, (a.y + b.y + c.y + d.y) / 4});
      }
  g.rule = domain_rule::triangle;
  return g;
}

/// random_map(seed, n) with up to `features` dangling segments (length 0.2 to 0.6, random
/// direction) and isolated vertices (every third) at random points of [0.2, n - 0.2]^2, each
/// kept when the PSLG stays valid (no crossing, touching or duplicate): the features inside
/// faces that the decoupled pipeline keeps inside subdomains. Deterministic for a seed.
inline pslg random_map_with_features(std::uint32_t seed, int n = 6, int features = 8) {
  pslg g = random_map(seed, n);
  std::mt19937 rng(seed * 7919u + 1u);
  std::uniform_real_distribution<double> at(0.2, n - 0.2), length(0.2, 0.6),
      turn(0.0, 2.0 * std::numbers::pi);
  for (int t = 0; t < features; ++t) {
    pslg trial = g;
    const point p{at(rng), at(rng)};
    const double a = turn(rng), l = length(rng);
    const point q{p.x + l * std::cos(a), p.y + l * std::sin(a)};
    if (t % 3 == 2)
      trial.add_vertex(p);
    else if (q.x > 0.0 && q.y > 0.0 && q.x < n && q.y < n)
      trial.add_segment(trial.add_vertex(p), trial.add_vertex(q));
    else
      continue;
    try {
      validate(trial, {.check_domain = false});
    } catch (const geometry_error&) {
      continue;
    }
    g = std::move(trial);
  }
  return g;
}

/// An arrangement of random_arrangement(7) before its 10 deg filter, by Triangle's rule: two
/// segments leave the vertex (1, 0.168) at about 0.2 deg and cross the whole square. With
/// circumcentre refinement the CGAL kernel refused it (a rounded split point fell beyond the
/// other segment); with off-centres it meshes it, the triangles in the small angle exempt by
/// the cluster rule. The kernel's test and the fuzz target's seed corpus use it.
inline pslg sub_degree_angle_domain() {
  std::istringstream in(R"(# pdd .poly: vertices <#> <dim> <#attributes> <#markers>
21 2 0 1
1 0 0 0
2 0.16820172248941206 0 0
3 0.695691668343259 0 0
4 1 0 0
5 1 0.16820172248941206 0
6 1 0.695691668343259 0
7 1 1 0
8 0.695691668343259 1 0
9 0.16820172248941206 1 0
10 0 1 0
11 0 0.695691668343259 0
12 0 0.16820172248941206 0
13 0.22681582160233213 0.25735874195924735 0
14 0.1716645008941692 0.3504092122288734 0
15 0.1722126783361483 0.5999858998232309 0
16 0.3797007097994091 0.38715307713619274 0
17 0.37457747206113295 0.6491512232554792 0
18 0.3815167528171107 0.8515433827913961 0
19 0.630091527254085 0.3705872874781643 0
20 0.5608863314584913 0.8348916207593444 0
21 0.7559803333674827 0.2028095094333075 0
# segments <#> <#markers>
19 1
1 1 2 0
2 2 3 0
3 3 4 0
4 4 5 0
5 5 6 0
6 6 7 0
7 7 8 0
8 8 9 0
9 9 10 0
10 10 11 0
11 11 12 0
12 12 1 0
13 15 5 0
14 5 11 0
15 11 13 0
16 8 20 0
17 11 8 0
18 8 6 0
19 13 3 0
# holes
0
)");
  pslg g = parse_poly(in, "sub-degree.poly", "");
  g.rule = domain_rule::triangle;
  return g;
}

/// The unit square with two segments from (0, 0.3) to the right side, ending at (1, 0.7) and
/// (1, 0.7 + 2e-16): an angle of about 2e-16 rad, valid (exact predicates: the segments meet
/// only at their common end) but beyond double precision: a split point of one, rounded, falls
/// on the other side of the other, and the CGAL kernel refuses it with an
/// unresolvable_input_error ("cannot be split").
inline pslg unresolvable_angle_domain() {
  pslg g;
  for (const point p : {point{0, 0}, point{1, 0}, point{1, 0.7}, point{1, 0.7 + 2e-16}, point{1, 1},
                        point{0, 1}, point{0, 0.3}})
    g.add_vertex(p);
  for (const auto& [a, b] :
       {std::pair{0, 1}, std::pair{1, 2}, std::pair{2, 3}, std::pair{3, 4}, std::pair{4, 5},
        std::pair{5, 6}, std::pair{6, 0}, std::pair{6, 2}, std::pair{6, 3}})
    g.add_segment(static_cast<index_t>(a), static_cast<index_t>(b));
  g.rule = domain_rule::triangle;
  return g;
}

/// A 12 x 6 section in three layers (interfaces y = 2 and y = 4) cut by two thrust faults:
/// one from (1, 0) dipping 30 deg to the top side, one from (6, 0) dipping 40 deg to the right
/// side. Every fault end and crossing is a corner below 60 deg on a segment between two faces
/// (8 caps); 9 faces, each with a region point whose attribute is its layer (1, 2, 3 from the
/// bottom), so a triangle's attribute is the layer its centroid's y lies in.
inline pslg faulted_layers() {
  pslg g;
  const double run1 = 1 / std::tan(std::numbers::pi / 6),
               run2 = 1 / std::tan(2 * std::numbers::pi / 9);
  const auto f1 = [&](double y) { return point{1 + run1 * y, y}; };
  const auto f2 = [&](double y) { return point{6 + run2 * y, y}; };
  const double y2r = 6 / run2; // where the second fault meets the right side
  const std::vector<point> outer = {{0, 0},    f1(0),   f2(0), {12, 0}, {12, 2}, {12, 4},
                                    {12, y2r}, {12, 6}, f1(6), {0, 6},  {0, 4},  {0, 2}};
  g.add_loop(outer, 1);                                               // vertices 0..11
  const index_t x12 = g.add_vertex(f1(2)), x22 = g.add_vertex(f2(2)); // 12, 13
  const index_t x14 = g.add_vertex(f1(4)), x24 = g.add_vertex(f2(4)); // 14, 15
  for (const auto& [a, b] : std::vector<std::pair<index_t, index_t>>{
           {11, x12}, {x12, x22}, {x22, 4}, {10, x14}, {x14, x24}, {x24, 5}})
    g.add_segment(a, b, 2); // the layer interfaces
  for (const auto& [a, b] : std::vector<std::pair<index_t, index_t>>{
           {1, x12}, {x12, x14}, {x14, 8}, {2, x22}, {x22, x24}, {x24, 6}})
    g.add_segment(a, b, 3); // the faults
  const point seeds[] = {{1.2, 1}, {5, 1}, {10, 1},     {3, 3},     {8, 3},
                         {11, 3},  {3, 5}, {11.5, 5.8}, {11.6, 4.3}};
  for (int r = 0; r < 9; ++r)
    g.regions.push_back({seeds[r], static_cast<double>(1 + r / 3), -1.0});
  g.rule = domain_rule::triangle;
  return g;
}

} // namespace pdd::test
