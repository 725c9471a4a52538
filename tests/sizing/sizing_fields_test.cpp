// The SizingField models against hand-computed values: interpolation, m/M bounds, the grid
// rule for callables, expression errors, the file readers.
#include <pdd/errors.hpp>
#include <pdd/io/area_grid.hpp>
#include <pdd/io/background_mesh.hpp>
#include <pdd/sizing/analytic.hpp>
#include <pdd/sizing/any_sizing.hpp>
#include <pdd/sizing/background_mesh.hpp>
#include <pdd/sizing/expression.hpp>
#include <pdd/sizing/grid.hpp>
#include <pdd/sizing/min_sizing.hpp>
#include <pdd/sizing/sizing_range.hpp>
#include <pdd/sizing/uniform.hpp>

#include "test_support.hpp"

#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace sizing_fields_test {
namespace {

using pdd::bbox;
using pdd::point;
constexpr double inf = std::numeric_limits<double>::infinity();

void write(const std::filesystem::path& p, const std::string& text) {
  std::ofstream(p) << text;
}

template <class F>
std::string sizing_error_of(F&& f) {
  try {
    f();
  } catch (const pdd::sizing_error& e) {
    return e.what();
  }
  return "no sizing_error";
}

TEST(UniformSizing, RangeIsExact) {
  const pdd::uniform_sizing u{0.25};
  EXPECT_EQ(u.area_at({3, 4}), 0.25);
  const pdd::sizing_bounds r = pdd::sizing_range(u, bbox{0, 0, 1, 1});
  EXPECT_EQ(r.lo, 0.25);
  EXPECT_EQ(r.hi, 0.25);
  EXPECT_EQ(pdd::sizing_range(u, bbox{}).lo, inf); // empty box
}

// f = 1e-3 + (x - 0.5037)^2 + (y - 0.3011)^2: its minimum 1e-3 lies between the nodes of the
// 64 x 64 evaluation grid (spacing 1/64), where every node value is > 1.0137e-3.
double bowl(point p) {
  return 1e-3 + (p.x - 0.5037) * (p.x - 0.5037) + (p.y - 0.3011) * (p.y - 0.3011);
}

TEST(AnalyticSizing, GridRuleBoundsAMinimumBetweenNodes) {
  const pdd::analytic_sizing f{&bowl};
  double node_min = inf;
  for (int j = 0; j <= 64; ++j)
    for (int i = 0; i <= 64; ++i)
      node_min = std::min(node_min, bowl({i / 64.0, j / 64.0}));
  ASSERT_GT(node_min, 1.001e-3); // a few samples (even all nodes) overestimate m
  const pdd::sizing_bounds r = pdd::sizing_range(f, bbox{0, 0, 1, 1});
  EXPECT_LE(r.lo, 1e-3); // a true lower bound
  // by the rule: the smallest node value less the margin 2 (Dxx + Dyy) / 8 = h^2 (a quadratic
  // of curvature 2 has second differences 2 h^2 along x and along y)
  EXPECT_NEAR(r.lo, node_min - 1.0 / (64.0 * 64.0), 1e-12);
  const double corner_max = bowl({1, 1});
  EXPECT_GE(r.hi, corner_max); // maximum at the corner (1, 1)
  EXPECT_LT(r.hi, 1.1 * corner_max);
  // many random boxes: the bound holds against dense sampling inside each
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int c = 0; c < 200; ++c) {
    const double x0 = u(rng), y0 = u(rng);
    const bbox b{x0, y0, x0 + 0.3 * u(rng), y0 + 0.3 * u(rng)};
    const pdd::sizing_bounds rb = pdd::sizing_range(f, b, {.cells = 8});
    for (int k = 0; k < 200; ++k) {
      const point p{b.xmin + u(rng) * b.width(), b.ymin + u(rng) * b.height()};
      ASSERT_GE(bowl(p), rb.lo) << "case " << c;
      ASSERT_LE(bowl(p), rb.hi) << "case " << c;
    }
  }
}

// The grid rule cell by cell, written out directly: per cell, the corner range widened by
// 2 (Dxx + Dyy) / 8, with Dxx, Dyy the largest |second differences| over the nodes of the cell
// and of its 8 neighbours (the second difference of a boundary node taken at the nearest node
// with two neighbours; an infinite corner: hi = inf, lo = half the smallest finite corner).
pdd::sizing_bounds grid_rule_by_hand(const pdd::detail::sampled_grid& g) {
  const auto at = [&](std::size_t i, std::size_t j) { return g.v[j * (g.nx + 1) + i]; };
  const auto d2 = [&](std::size_t i, std::size_t j, bool along_x) {
    const std::size_t n = along_x ? g.nx : g.ny;
    if (n < 2) return 0.0;
    const std::size_t c = std::clamp<std::size_t>(along_x ? i : j, 1, n - 1);
    const double d = along_x ? at(c - 1, j) - 2 * at(c, j) + at(c + 1, j)
                             : at(i, c - 1) - 2 * at(i, c) + at(i, c + 1);
    return std::isfinite(d) ? std::abs(d) : 0.0;
  };
  pdd::sizing_bounds r{inf, 0.0};
  for (std::size_t j = 0; j < std::max<std::size_t>(g.ny, 1); ++j)
    for (std::size_t i = 0; i < std::max<std::size_t>(g.nx, 1); ++i) {
      double lo = inf, hi = 0.0, dxx = 0.0, dyy = 0.0;
      for (std::size_t c = 0; c < 4; ++c) {
        const double v = at(std::min(i + (c & 1), g.nx), std::min(j + (c >> 1), g.ny));
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
      for (std::size_t jj = j > 0 ? j - 1 : 0; jj <= std::min(j + 2, g.ny); ++jj)
        for (std::size_t ii = i > 0 ? i - 1 : 0; ii <= std::min(i + 2, g.nx); ++ii) {
          dxx = std::max(dxx, d2(ii, jj, true));
          dyy = std::max(dyy, d2(ii, jj, false));
        }
      if (std::isinf(lo)) {
        r.hi = inf;
        continue;
      }
      const double m = 2.0 * (dxx + dyy) / 8.0;
      r.lo = std::min(r.lo, std::isinf(hi) ? 0.5 * lo : lo - m);
      r.hi = std::max(r.hi, hi + m);
    }
  if (r.hi == 0.0) r.hi = inf;
  return r;
}

TEST(AnalyticSizing, GridRuleMarginIsLocalToEachCellsNeighbourhood) {
  // random grids with sharp local spikes (a margin window one node too small or too large
  // changes the bound) and infinite nodes; the result must be the rule's, bitwise
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int c = 0; c < 2000; ++c) {
    const std::size_t nx = rng() % 9, ny = rng() % 9;
    pdd::detail::sampled_grid g{nx, ny, std::vector<double>((nx + 1) * (ny + 1))};
    for (double& v : g.v)
      v = rng() % 13 == 0 ? inf : (rng() % 5 == 0 ? 10.0 : 1.0) * u(rng);
    const pdd::sizing_bounds want = grid_rule_by_hand(g), got = pdd::detail::grid_bounds(g);
    ASSERT_EQ(got.lo, want.lo) << "case " << c << " (" << nx << " x " << ny << ")";
    ASSERT_EQ(got.hi, want.hi) << "case " << c << " (" << nx << " x " << ny << ")";
  }
}

double shallow_bowl(point p) {
  return 1e-3 * (1.0 + bowl(p) - 1e-3);
}

TEST(AnalyticSizing, MeshScaleGridFollowsTheSmallestAreaAndStillBounds) {
  std::atomic<long> calls{0};
  const auto counted = [&calls](double (*f)(point)) {
    return pdd::analytic_sizing{[&calls, f](point p) {
      ++calls;
      return f(p);
    }};
  };
  const pdd::sizing_range_options mesh{.cells = 64, .mesh_resolution = 1.0};
  // a coarse field on the unit box (m ~ 1: one triangle's edge spans the box): the 8 x 8 grid
  const auto coarse = counted([](point p) { return 1.0 + 0.1 * p.x; });
  const pdd::sizing_bounds c = pdd::sizing_range(coarse, bbox{0, 0, 1, 1}, mesh);
  EXPECT_EQ(calls.load(), 81);
  EXPECT_NEAR(c.lo, 1.0, 1e-12);
  EXPECT_NEAR(c.hi, 1.1, 1e-12);
  // m = 1e-3: ceil(1 / sqrt(1e-3)) = 32 cells a side
  calls = 0;
  const auto middle = counted([](point p) { return 1e-3 * (1.0 + p.x); });
  const pdd::sizing_bounds r = pdd::sizing_range(middle, bbox{0, 0, 1, 1}, mesh);
  EXPECT_EQ(calls.load(), 81 + 33 * 33);
  EXPECT_NEAR(r.lo, 1e-3, 1e-15);
  EXPECT_NEAR(r.hi, 2e-3, 1e-15);
  // a field finer than 64 cells can resolve: the full grid
  calls = 0;
  const auto finest = counted([](point p) { return 1e-6 * (1.0 + p.x); });
  (void)pdd::sizing_range(finest, bbox{0, 0, 1, 1}, mesh);
  EXPECT_EQ(calls.load(), 81 + 65 * 65);
  // no positive bound from the 8 x 8 grid (the bowl's margin there is 1/64): the full grid
  calls = 0;
  const auto fine = counted(&bowl);
  EXPECT_LE(pdd::sizing_range(fine, bbox{0, 0, 1, 1}, mesh).lo, 1e-3);
  EXPECT_EQ(calls.load(), 81 + 65 * 65);
  // any_sizing and min_sizing pass the options on to the field they hold
  calls = 0;
  const pdd::any_sizing held{coarse};
  (void)pdd::sizing_range(pdd::min_sizing(pdd::uniform_sizing{2.0}, held), bbox{0, 0, 1, 1}, mesh);
  EXPECT_EQ(calls.load(), 81);
  // the bound holds against dense sampling in random boxes (a bowl of minimum 1e-3 between
  // the nodes, shallow enough for the mesh-scale grid to apply)
  const pdd::analytic_sizing shallow{&shallow_bowl};
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int k = 0; k < 200; ++k) {
    const double x0 = u(rng), y0 = u(rng);
    const bbox b{x0, y0, x0 + 0.5 * u(rng), y0 + 0.5 * u(rng)};
    const pdd::sizing_bounds rb = pdd::sizing_range(shallow, b, mesh);
    for (int s = 0; s < 200; ++s) {
      const point p{b.xmin + u(rng) * b.width(), b.ymin + u(rng) * b.height()};
      ASSERT_GE(shallow_bowl(p), rb.lo) << "box " << k;
      ASSERT_LE(shallow_bowl(p), rb.hi) << "box " << k;
    }
  }
}

TEST(AnalyticSizing, RangeFunctionIsUsedAsGiven) {
  const pdd::analytic_sizing f{&bowl, [](const bbox&) { return pdd::sizing_bounds{1e-3, 2.0}; }};
  static_assert(pdd::BoundedSizingField<decltype(f)>);
  const pdd::sizing_bounds r = pdd::sizing_range(f, bbox{0, 0, 1, 1});
  EXPECT_EQ(r.lo, 1e-3);
  EXPECT_EQ(r.hi, 2.0);
}

TEST(AnalyticSizing, NonPositiveValueIsAnError) {
  const pdd::analytic_sizing f{[](point p) { return p.x - 0.5; }};
  const std::string msg = sizing_error_of([&] { (void)pdd::sizing_range(f, bbox{0, 0, 1, 1}); });
  EXPECT_NE(msg.find("must be > 0"), std::string::npos) << msg;
}

TEST(ExpressionSizing, EvaluatesWithXAndY) {
  const pdd::expression_sizing f("1e-4*(1+10*x^2) + 0*y");
  EXPECT_DOUBLE_EQ(f.area_at({0.5, 2.0}), 1e-4 * 3.5);
  const pdd::expression_sizing g("sqrt(x^2+y^2) + exp(0) + sin(_pi/2)");
  EXPECT_DOUBLE_EQ(g.area_at({3, 4}), 7.0);
  EXPECT_EQ(g.kind(), std::string("expression"));
}

TEST(ExpressionSizing, ErrorsNameTheColumn) {
  struct bad {
    const char* text;
    std::size_t column;
  };
  // 1-based columns of the bad token; the end of the text + 1 when it ends too early
  for (const bad& b : {bad{"1+z*2", 3}, bad{"1e-4*(1+", 9}, bad{"x**2", 3}, bad{"foo(x)", 1}}) {
    try {
      pdd::expression_sizing f(b.text);
      ADD_FAILURE() << b.text << " parsed";
    } catch (const pdd::sizing_error& e) {
      EXPECT_EQ(e.column(), b.column) << b.text << ": " << e.what();
      EXPECT_NE(std::string(e.what()).find("column " + std::to_string(b.column)), std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find(b.text), std::string::npos) << e.what();
    }
  }
}

TEST(ExpressionSizing, NonPositiveValueNamesThePoint) {
  const pdd::expression_sizing f("x-1");
  const std::string msg = sizing_error_of([&] { (void)f.area_at({0.5, 2}); });
  EXPECT_NE(msg.find("(0.500000, 2.000000)"), std::string::npos) << msg;
}

TEST(ExpressionSizing, ConcurrentEvaluationMatchesSequential) {
  const pdd::expression_sizing f("1e-3*(1+x*x+3*y)");
  std::vector<double> seq(20000), par(20000);
  const auto pt = [](std::size_t i) { return point{i * 1e-4, (i % 97) * 1e-2}; };
  for (std::size_t i = 0; i < seq.size(); ++i)
    seq[i] = f.area_at(pt(i));
  const pdd::expression_sizing copy = f; // copies share the parsers
  tbb::parallel_for(std::size_t{0}, par.size(),
                    [&](std::size_t i) { par[i] = copy.area_at(pt(i)); });
  EXPECT_EQ(seq, par);
}

// Two triangles over the unit square, vertex areas 1, 2, 3, 4.
pdd::background_mesh_sizing square_mesh(pdd::background_mesh_sizing::interpolation mode,
                                        std::vector<double> values) {
  return {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 1, 2}, {0, 2, 3}}, std::move(values), mode};
}

TEST(BackgroundMeshSizing, LinearInterpolationPerVertex) {
  const auto f = square_mesh(pdd::background_mesh_sizing::interpolation::per_vertex, {1, 2, 3, 4});
  // (0.75, 0.25) in (0,1,2): barycentric 0.25, 0.5, 0.25 -> 1/4 + 2/2 + 3/4 = 2
  EXPECT_DOUBLE_EQ(f.area_at({0.75, 0.25}), 2.0);
  // (0.25, 0.75) in (0,2,3): 0.25, 0.25, 0.5 -> 1/4 + 3/4 + 4/2 = 3
  EXPECT_DOUBLE_EQ(f.area_at({0.25, 0.75}), 3.0);
  EXPECT_DOUBLE_EQ(f.area_at({1, 1}), 3.0);
  EXPECT_EQ(f.area_at({2, 2}), inf);
  const pdd::sizing_bounds r = f.range(bbox{0.6, 0.1, 0.9, 0.2});
  EXPECT_EQ(r.lo, 1.0);
  EXPECT_EQ(r.hi, 4.0);
  EXPECT_EQ(f.range(bbox{5, 5, 6, 6}).lo, inf);
}

TEST(BackgroundMeshSizing, RangeOfAFineMeshIsTheNodeRange) {
  // 20 x 20 squares, each split in two, area 1 + x + 2y at the nodes; linear, so the range
  // over the cells a box meets is the min/max of their nodes
  std::vector<point> v;
  std::vector<double> a;
  std::vector<std::array<pdd::index_t, 3>> t;
  for (int j = 0; j <= 20; ++j)
    for (int i = 0; i <= 20; ++i) {
      v.push_back({i / 20.0, j / 20.0});
      a.push_back(1 + i / 20.0 + 2 * j / 20.0);
    }
  for (pdd::index_t j = 0; j < 20; ++j)
    for (pdd::index_t i = 0; i < 20; ++i) {
      const pdd::index_t k = j * 21 + i;
      t.push_back({k, k + 1, k + 22});
      t.push_back({k, k + 22, k + 21});
    }
  const pdd::background_mesh_sizing f(v, t, a,
                                      pdd::background_mesh_sizing::interpolation::per_vertex);
  EXPECT_DOUBLE_EQ(f.area_at({0.33, 0.71}), 1 + 0.33 + 2 * 0.71);
  const pdd::sizing_bounds r = f.range(bbox{0.31, 0.42, 0.52, 0.58});
  EXPECT_DOUBLE_EQ(r.lo, 1 + 0.30 + 2 * 0.40); // nodes of the cells the box meets
  EXPECT_DOUBLE_EQ(r.hi, 1 + 0.55 + 2 * 0.60);
}

TEST(BackgroundMeshSizing, PiecewiseConstantPerTriangle) {
  const auto f = square_mesh(pdd::background_mesh_sizing::interpolation::per_triangle, {5, -1});
  EXPECT_EQ(f.area_at({0.75, 0.25}), 5.0);
  EXPECT_EQ(f.area_at({0.25, 0.75}), inf); // <= 0: no constraint (Triangle's .area)
  EXPECT_EQ(f.area_at({0.5, 0.5}), 5.0);   // on the shared edge: the smaller triangle id
  EXPECT_EQ(f.range(bbox{0, 0, 1, 1}).lo, 5.0);
}

TEST(BackgroundMeshSizing, BadInputIsNamed) {
  using m = pdd::background_mesh_sizing;
  EXPECT_NE(sizing_error_of([] {
              square_mesh(m::interpolation::per_vertex, {1, 2, 0, 4});
            }).find("vertex 2"),
            std::string::npos);
  EXPECT_NE(sizing_error_of([] {
              m({{0, 0}, {1, 0}, {2, 0}}, {{0, 1, 2}}, {1, 1, 1}, m::interpolation::per_vertex);
            }).find("triangle 0 is degenerate"),
            std::string::npos);
  EXPECT_NE(sizing_error_of([] {
              m({{0, 0}, {1, 0}, {2, 0}}, {{0, 1, 7}}, {1, 1, 1}, m::interpolation::per_vertex);
            }).find("refers to vertex 7"),
            std::string::npos);
}

TEST(GridSizing, BilinearAndExactRange) {
  // 3 x 2 nodes from (1, 2), spacing 0.5 x 1
  const pdd::grid_sizing g({1, 2}, 0.5, 1.0, 3, 2, {1, 2, 4, 3, 5, 9});
  EXPECT_DOUBLE_EQ(g.area_at({1.25, 2.5}), (1 + 2 + 3 + 5) / 4.0);
  EXPECT_DOUBLE_EQ(g.area_at({1.5, 2.25}), 0.75 * 2 + 0.25 * 5);
  EXPECT_DOUBLE_EQ(g.area_at({2, 3}), 9.0);
  EXPECT_EQ(g.area_at({0.9, 2.5}), inf);
  pdd::sizing_bounds r = g.range(bbox{1.6, 2.1, 1.9, 2.2});
  EXPECT_EQ(r.lo, 2.0);
  EXPECT_EQ(r.hi, 9.0);
  r = g.range(bbox{1.0, 2.0, 1.5, 3.0}); // exactly the first cell
  EXPECT_EQ(r.lo, 1.0);
  EXPECT_EQ(r.hi, 5.0);
  EXPECT_EQ(g.range(bbox{0, 0, 1.2, 2.5}).hi, inf); // reaches outside the grid
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> ux(1.6, 1.9), uy(2.1, 2.2);
  for (int k = 0; k < 1000; ++k) {
    const double a = g.area_at({ux(rng), uy(rng)});
    ASSERT_GE(a, 2.0);
    ASSERT_LE(a, 9.0);
  }
}

TEST(MinSizing, CombinesFieldsAndBounds) {
  const pdd::grid_sizing g({0, 0}, 1, 1, 2, 2, {1, 2, 3, 4});
  const pdd::min_sizing m(g, pdd::uniform_sizing{2.5});
  EXPECT_DOUBLE_EQ(m.area_at({0.5, 0.5}), 2.5);
  EXPECT_DOUBLE_EQ(m.area_at({0, 0}), 1.0);
  const pdd::sizing_bounds r = m.range(bbox{0, 0, 1, 1});
  EXPECT_EQ(r.lo, 1.0);
  EXPECT_EQ(r.hi, 2.5);
  EXPECT_EQ(m.kind(), "min(grid, uniform)");
  const pdd::any_sizing any = m;
  EXPECT_EQ(any.kind(), "min(grid, uniform)");
  EXPECT_DOUBLE_EQ(any.area_at({0, 0}), 1.0);
  EXPECT_EQ(pdd::any_sizing{}.area_at({0, 0}), inf);
  EXPECT_EQ(pdd::any_sizing{}.kind(), "none");
}

TEST(SizingFiles, BackgroundMeshPerVertexAndPerTriangle) {
  const auto stem = pdd::test::temp_path("bg");
  write(stem.string() + ".node", "4 2 1 0\n1 0 0 1\n2 1 0 2\n3 1 1 3\n4 0 1 4\n");
  write(stem.string() + ".ele", "# two triangles\n2 3 0\n1 1 2 3\n2 1 3 4\n");
  std::filesystem::remove(stem.string() + ".area");
  const pdd::background_mesh_sizing f = pdd::read_background_mesh(stem.string() + ".node");
  EXPECT_DOUBLE_EQ(f.area_at({0.75, 0.25}), 2.0);
  write(stem.string() + ".node", "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n");
  write(stem.string() + ".area", "2\n1 0.5\n2 -1\n");
  const pdd::background_mesh_sizing g = pdd::read_background_mesh(stem.string() + ".node");
  EXPECT_EQ(g.area_at({0.75, 0.25}), 0.5);
  EXPECT_EQ(g.area_at({0.25, 0.75}), inf);
  write(stem.string() + ".area", "2\n1 0.5\n");
  try {
    (void)pdd::read_background_mesh(stem.string() + ".node");
    ADD_FAILURE() << "truncated .area accepted";
  } catch (const pdd::input_error& e) {
    EXPECT_EQ(e.line(), 3u) << e.what();
    EXPECT_NE(e.file().find("bg.area"), std::string::npos);
  }
  std::filesystem::remove(stem.string() + ".area");
  try {
    (void)pdd::read_background_mesh(stem.string() + ".node");
    ADD_FAILURE() << "no areas accepted";
  } catch (const pdd::input_error& e) {
    EXPECT_NE(std::string(e.what()).find("area"), std::string::npos) << e.what();
  }
  write(stem.string() + ".ele", "2 3 0\n1 1 2 3\n2 1 3 5\n");
  write(stem.string() + ".node", "4 2 1 0\n1 0 0 1\n2 1 0 2\n3 1 1 3\n4 0 1 4\n");
  try {
    (void)pdd::read_background_mesh(stem.string() + ".node");
    ADD_FAILURE() << "vertex 5 accepted";
  } catch (const pdd::input_error& e) {
    EXPECT_EQ(e.line(), 3u) << e.what();
  }
}

TEST(SizingFiles, AreaGrid) {
  const auto path = pdd::test::temp_path("grid.txt");
  write(path, "# nx ny x0 y0 dx dy\n3 2 1 2 0.5 1\n1 2 4\n\n3 5 9  # top row\n");
  const pdd::grid_sizing g = pdd::read_area_grid(path);
  EXPECT_DOUBLE_EQ(g.area_at({1.25, 2.5}), 2.75);
  struct bad {
    const char* text;
    std::size_t line;
    const char* says;
  };
  for (const bad& b : {bad{"3 2 1 2 0.5 1\n1 2 4\n3 5\n", 3, "3 fields"},
                       bad{"3 2 1 2 0.5 1\n1 2 4\n3 5 x\n", 3, "'x'"},
                       bad{"3 2 1 2 0 1\n1 2 4\n3 5 9\n", 1, "> 0"},
                       bad{"3 2 1 2 0.5 1\n1 -2 4\n3 5 9\n", 2, "node (1, 0)"},
                       bad{"3 2 1 2 0.5 1\n1 2 4\n", 3, "ended"},
                       bad{"3 2 1 2 0.5 1\n1 2 4\n3 5 9\n7\n", 4, "end of the file"}}) {
    write(path, b.text);
    try {
      (void)pdd::read_area_grid(path);
      ADD_FAILURE() << b.text;
    } catch (const pdd::input_error& e) {
      EXPECT_EQ(e.line(), b.line) << e.what();
      EXPECT_NE(std::string(e.what()).find(b.says), std::string::npos) << e.what();
    }
  }
}

} // namespace

} // namespace sizing_fields_test
