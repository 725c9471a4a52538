// Graded MADD (dissertation 4.4): density weights from boundary vertices (with the
// interpolation factor p), from weighted points (background nodes, grids), the policy
// u * area + a * weight, and the area-ratio stopping rule; hand-computed weights, valid
// decompositions, bitwise determinism across thread counts, and clear errors.
#include <pdd/io/poly.hpp>
#include <pdd/io/weight_files.hpp>
#include <pdd/madd/decompose.hpp>
#include <pdd/madd/graded_weights.hpp>
#include <pdd/madd/validate_decomposition.hpp>
#include <pdd/sizing/analytic.hpp>
#include <pdd/sizing/grid.hpp>

#include <decomposition_compare.hpp>
#include <test_domains.hpp>
#include <test_files.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

namespace madd_graded_test {
namespace {

using pdd::madd_leaf_view;
using pdd::point;

/// A leaf view over owned loops.
struct leaf {
  std::vector<std::vector<point>> loops;
  double area = 0.0;
  madd_leaf_view view() const {
    madd_leaf_view v;
    for (const auto& l : loops)
      v.loops.emplace_back(l);
    v.area = area;
    return v;
  }
};

/// The unit square with weight 4 on its left side's vertices (0,0) and (0,1), 0 on the right.
pdd::boundary_vertex_weights left_weights(double p) {
  return {pdd::test::unit_square(), {4.0, 0.0, 0.0, 4.0}, p};
}

TEST(MaddGradedWeights, BoundaryPointsInterpolateAlongTheirSegment) {
  const auto w = left_weights(0.0);
  // left half: (0,0)=4, (0.5,0)=2 on the bottom side, (0.5,1)=2 on the top side, (0,1)=4
  EXPECT_DOUBLE_EQ(w.leaf_weight(leaf{{{{0, 0}, {0.5, 0}, {0.5, 1}, {0, 1}}}, 0.5}.view()), 12.0);
  // right half: 2 + 0 + 0 + 2
  EXPECT_DOUBLE_EQ(w.leaf_weight(leaf{{{{0.5, 0}, {1, 0}, {1, 1}, {0.5, 1}}}, 0.5}.view()), 4.0);
  double v = -1;
  EXPECT_TRUE(w.boundary_weight({0, 0.25}, v));
  EXPECT_DOUBLE_EQ(v, 4.0);
  EXPECT_TRUE(w.boundary_weight({0.25, 1}, v));
  EXPECT_DOUBLE_EQ(v, 3.0);
  EXPECT_FALSE(w.boundary_weight({0.25, 0.5}, v));
}

TEST(MaddGradedWeights, InterfacePointsScaleWithP) {
  // (0.5,0.5) is interior: between the anchors (0.5,0) (W = 2) and (0,0.5) (W = 4), half way
  // by arc length: p * 3. The loop's total is 4 + 2 + 3p + 4.
  const leaf quarter{{{{0, 0}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}}}, 0.25};
  for (const double p : {0.0, 0.5, 1.0})
    EXPECT_DOUBLE_EQ(left_weights(p).leaf_weight(quarter.view()), 10.0 + 3.0 * p) << "p " << p;
  // one anchor (0,0.5), W = 4: the two interface points get p * 4 each
  const leaf wedge{{{{0, 0.5}, {0.5, 0.25}, {0.5, 0.75}}}, 0.0625};
  EXPECT_DOUBLE_EQ(left_weights(0.0).leaf_weight(wedge.view()), 4.0);
  EXPECT_DOUBLE_EQ(left_weights(1.0).leaf_weight(wedge.view()), 12.0);
  // no anchor at all: 0 for every p
  const leaf inner{{{{0.25, 0.25}, {0.75, 0.25}, {0.75, 0.75}, {0.25, 0.75}}}, 0.25};
  EXPECT_EQ(left_weights(1.0).leaf_weight(inner.view()), 0.0);
}

TEST(MaddGradedWeights, PointWeightsCountTheClosedLeafOnly) {
  // nodes of a 5 x 5 grid over [0,1]^2 (spacing 0.25), weight 1 + i + 10 j
  const auto pw = pdd::point_weights::on_grid({0, 0}, 0.25, 0.25, 5, 5,
                                              [](point q) { return 1.0 + 4.0 * q.x + 40.0 * q.y; });
  ASSERT_EQ(pw.size(), 25u);
  // [0,0.5]^2 holds nodes i, j in {0,1,2} (its boundary included): sum of 1 + i + 10 j
  // = 9 + 3 * 3 + 10 * 3 * 3 = 108
  EXPECT_DOUBLE_EQ(pw.leaf_weight(leaf{{{{0, 0}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}}}, 0.25}.view()),
                   108.0);
  // the same square with the hole [0.2,0.3]^2 around node (1,1) (weight 12): 96; a hole
  // whose boundary passes through node (1,1) keeps it
  EXPECT_DOUBLE_EQ(pw.leaf_weight(leaf{{{{0, 0}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}},
                                        {{0.2, 0.2}, {0.2, 0.3}, {0.3, 0.3}, {0.3, 0.2}}},
                                       0.24}
                                      .view()),
                   96.0);
  EXPECT_DOUBLE_EQ(pw.leaf_weight(leaf{{{{0, 0}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}},
                                        {{0.25, 0.25}, {0.25, 0.3}, {0.3, 0.3}, {0.3, 0.25}}},
                                       0.2475}
                                      .view()),
                   108.0);
  // a triangle through nodes (0,0), (2,0), (0,2): the 6 nodes on or under its hypotenuse
  EXPECT_DOUBLE_EQ(pw.leaf_weight(leaf{{{{0, 0}, {0.5, 0}, {0, 0.5}}}, 0.125}.view()),
                   1 + 2 + 3 + 11 + 12 + 21);
}

double mean_area_touching_x(const pdd::decomposition& d, double x) {
  double sum = 0.0;
  int n = 0;
  for (const auto& s : d.subdomains) {
    bool touches = false;
    for (const auto& loop : s.loops)
      for (const auto v : loop)
        touches = touches || d.vertices[v].x == x;
    if (touches) {
      sum += s.area;
      ++n;
    }
  }
  return n ? sum / n : 0.0;
}

pdd::decomposition graded_square(double p, unsigned threads, std::size_t n = 32) {
  const pdd::pslg g = pdd::test::unit_square();
  pdd::madd_options o{.subdomains = n};
  o.threads = threads;
  o.split_policy =
      pdd::density_weight_policy(pdd::boundary_vertex_weights(g, {4.0, 0.0, 0.0, 4.0}, p),
                                 {.uniform_factor = 3.0, .weight_factor = 3.0, .interpolation = p});
  return pdd::decompose(g, o);
}

using pdd::test::expect_same_decomposition;

TEST(MaddGradedDecompose, WeightedSideGetsSmallerSubdomains) {
  const pdd::pslg g = pdd::test::unit_square();
  for (const double p : {0.0, 1.0}) {
    const pdd::decomposition d = graded_square(p, 1);
    EXPECT_EQ(d.subdomains.size(), 32u);
    const auto rep = pdd::validate_decomposition(d, g, {.min_angle_deg = 60.0});
    EXPECT_TRUE(rep.ok()) << rep.summary();
    const double left = mean_area_touching_x(d, 0.0), right = mean_area_touching_x(d, 1.0);
    EXPECT_GT(left, 0.0);
    EXPECT_LT(2.0 * left, right) << "p " << p; // the left side's subdomains are much smaller
  }
}

TEST(MaddGradedDecompose, InterpolationFactorChangesTheDecomposition) {
  const pdd::decomposition a = graded_square(0.0, 1), b = graded_square(1.0, 1);
  bool differ = a.vertices.size() != b.vertices.size();
  for (std::size_t i = 0; !differ && i < a.vertices.size(); ++i)
    differ = a.vertices[i].x != b.vertices[i].x || a.vertices[i].y != b.vertices[i].y;
  EXPECT_TRUE(differ);
}

TEST(MaddGradedDecompose, BitwiseIdenticalAcrossThreads) {
  expect_same_decomposition(graded_square(0.5, 1, 48), graded_square(0.5, 2, 48));
}

TEST(MaddGradedDecompose, BackgroundNodesConcentrateTheSubdomains) {
  // weights only near the corner (0,0) of the square with a hole: the subdomains there are
  // smaller than the mean
  const pdd::pslg g = pdd::test::square_with_hole();
  const auto pw = pdd::point_weights::on_grid({0, 0}, 0.1, 0.1, 31, 31,
                                              [](point q) { return q.x + q.y < 0.75 ? 1.0 : 0.0; });
  for (const unsigned threads : {1u, 2u}) {
    pdd::madd_options o{.subdomains = 40};
    o.threads = threads;
    o.split_policy = pdd::density_weight_policy(pw, {.uniform_factor = 1.0, .weight_factor = 1.0});
    const pdd::decomposition d = pdd::decompose(g, o);
    ASSERT_EQ(d.subdomains.size(), 40u);
    EXPECT_TRUE(pdd::validate_decomposition(d, g, {.min_angle_deg = 60.0}).ok());
    const auto leaves = pdd::leaves_of(d);
    double corner_area = 0.0;
    for (std::size_t s = 0; s < d.subdomains.size(); ++s)
      if (pdd::detail::leaf_polygons(leaves.views[s]).contains({0.0, 0.0}))
        corner_area = d.subdomains[s].area;
    EXPECT_GT(corner_area, 0.0);
    EXPECT_LT(corner_area, 8.0 / 40.0 / 4.0); // a quarter of the mean area at most
  }
}

/// Required subdomain area 0.002 + 0.05 x on [0,1]^2 (a callable: bounded on a grid).
auto ramp_area() {
  return pdd::analytic_sizing{[](point q) { return 0.002 + 0.05 * q.x; }};
}

TEST(MaddGradedDecompose, AreaRatioRuleHoldsOnEveryFinalSubdomain) {
  const pdd::pslg g = pdd::test::unit_square();
  pdd::decomposition first;
  for (const unsigned threads : {1u, 2u}) {
    pdd::madd_options o{.subdomains = 100000};
    o.threads = threads;
    o.split_policy = pdd::area_ratio_policy(ramp_area(), 1.0);
    const pdd::decomposition d = pdd::decompose(g, o);
    EXPECT_TRUE(pdd::validate_decomposition(d, g, {.min_angle_deg = 60.0}).ok());
    const auto leaves = pdd::leaves_of(d);
    const auto req = pdd::required_areas(ramp_area(), leaves.views);
    for (std::size_t s = 0; s < d.subdomains.size(); ++s)
      EXPECT_LE(d.subdomains[s].area, req[s]) << "subdomain " << s;
    // the field's integral of 1 / F over [0,1]^2 is 20 ln 26 = 65: at least that many
    EXPECT_GE(d.subdomains.size(), 65u);
    EXPECT_LT(d.subdomains.size(), 400u);
    EXPECT_LT(mean_area_touching_x(d, 0.0), mean_area_touching_x(d, 1.0) / 4.0);
    if (threads == 1)
      first = d;
    else
      expect_same_decomposition(first, d);
  }
}

TEST(MaddGradedDecompose, AreaRatioBoundScalesTheCount) {
  // a grid field (exact bounds): ratio 2 allows subdomains twice the required area
  const pdd::pslg g = pdd::test::unit_square();
  const pdd::grid_sizing f({0, 0}, 0.5, 0.5, 3, 3, std::vector<double>(9, 0.01));
  std::size_t counts[2];
  int k = 0;
  for (const double r : {1.0, 2.0}) {
    const pdd::decomposition d =
        pdd::decompose(g, {.subdomains = 100000, .split_policy = pdd::area_ratio_policy(f, r)});
    for (const auto& s : d.subdomains)
      EXPECT_LE(s.area / 0.01, r);
    counts[k++] = d.subdomains.size();
  }
  EXPECT_GE(counts[0], 100u);
  EXPECT_GE(counts[1], 50u);
  EXPECT_LT(counts[1], counts[0]);
}

template <class F>
void expect_error(F&& f, const std::string& part) {
  try {
    f();
    FAIL() << "no error; expected '" << part << "'";
  } catch (const pdd::error& e) {
    EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << e.what();
  }
}

TEST(MaddGradedErrors, BadOptionsAndWeights) {
  const pdd::pslg g = pdd::test::unit_square();
  const auto pw = pdd::point_weights({{0, 0}}, {1.0});
  expect_error([&] { (void)pdd::density_weight_policy(pw, {.uniform_factor = -1}); },
               "uniform factor u must be finite and >= 0");
  expect_error(
      [&] { (void)pdd::density_weight_policy(pw, {.uniform_factor = 0, .weight_factor = 0}); },
      "u and a cannot both be 0");
  expect_error([&] { (void)pdd::density_weight_policy(pw, {.interpolation = 1.5}); },
               "interpolation factor p must be in [0, 1]");
  expect_error([&] { (void)pdd::area_ratio_policy(ramp_area(), 0.0); },
               "area ratio bound must be finite and > 0");
  expect_error(
      [&] {
        (void)pdd::boundary_vertex_weights(g, {1, 2, 3}, 0.5);
      },
      "3 vertex weights for 4 vertices");
  expect_error(
      [&] {
        (void)pdd::boundary_vertex_weights(g, {1, 2, -3, 0}, 0.5);
      },
      "the weight of vertex 2 is -3");
  expect_error(
      [&] {
        (void)pdd::point_weights({{0, 0}, {1, 1}}, {1.0, -1.0});
      },
      "weighted point 1 (1.000000, 1.000000) has weight -1");
  expect_error([&] { (void)pdd::first_vertex_attribute(g); }, "<#attributes> is 0");
}

TEST(MaddGradedFiles, PolyVertexAttributesAreKeptAndWritten) {
  std::istringstream in("4 2 2 0\n1 0 0 5 7\n2 1 0 0 8\n3 1 1 0 9\n4 0 1 5 10\n"
                        "4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n");
  const pdd::pslg g = pdd::parse_poly(in, "w.poly");
  ASSERT_EQ(g.vertex_attribute_count, 2u);
  EXPECT_EQ(g.vertex_attributes, (std::vector<double>{5, 7, 0, 8, 0, 9, 5, 10}));
  EXPECT_EQ(pdd::first_vertex_attribute(g), (std::vector<double>{5, 0, 0, 5}));
  const std::string out = pdd::test::write_temp_file("graded_attr.poly", "");
  pdd::write_poly(out, g);
  const pdd::pslg back = pdd::read_poly(out);
  EXPECT_EQ(back.vertex_attribute_count, 2u);
  EXPECT_EQ(back.vertex_attributes, g.vertex_attributes);
}

TEST(MaddGradedFiles, WeightFilesReadAndReportFileLine) {
  const std::string node = pdd::test::write_temp_file(
      "graded_w.node", "# weights\n3 2 1 0\n1 0 0 2\n2 1 0 0\n3 0 1 1\n");
  const pdd::point_weights pw = pdd::read_node_weights(node);
  EXPECT_EQ(pw.size(), 3u);
  EXPECT_DOUBLE_EQ(pw.leaf_weight(leaf{{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}, 1}.view()), 3.0);
  const std::string bad_node =
      pdd::test::write_temp_file("graded_bad.node", "3 2 1 0\n1 0 0 2\n2 1 0 -1\n3 0 1 1\n");
  expect_error([&] { (void)pdd::read_node_weights(bad_node); },
               bad_node + ":3: expected the vertex weight to be >= 0, found -1");
  const std::string no_attr = pdd::test::write_temp_file("graded_noattr.node", "1 2 0 0\n1 0 0\n");
  expect_error([&] { (void)pdd::read_node_weights(no_attr); },
               no_attr +
                   ":1: expected exactly 1 vertex attribute (the density weight of the vertex)");
  const std::string grid = pdd::test::write_temp_file("graded_w.grid", "2 2 0 0 1 1\n0 1\n2 3\n");
  EXPECT_DOUBLE_EQ(
      pdd::read_weight_grid(grid).leaf_weight(leaf{{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}, 1}.view()),
      6.0);
  const std::string bad_grid =
      pdd::test::write_temp_file("graded_bad.grid", "2 2 0 0 1 1\n0 1\n2 -3\n");
  expect_error([&] { (void)pdd::read_weight_grid(bad_grid); },
               bad_grid + ":3: expected the weight at node (1, 1) to be >= 0, found -3");
}

} // namespace

} // namespace madd_graded_test
