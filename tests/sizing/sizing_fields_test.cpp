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
