// Meshing with sizing fields: the .poly regional areas against Triangle's counts, graded
// meshes of the bundled domains verified against the field (area <= F at every centroid,
// exact Delaunay, conformity, quality), monolithic and decoupled (the interim rule: the
// uniform path with k from the field's minimum), bitwise identical at 1 and 2 threads.
#include <pdd/errors.hpp>
#include <pdd/generate.hpp>
#include <pdd/geometry/model_domains.hpp>
#include <pdd/geometry/properties.hpp>
#include <pdd/io/poly.hpp>
#include <pdd/mesh/verify.hpp>
#include <pdd/shielding/shield_statistics.hpp>
#include <pdd/sizing/any_sizing.hpp>
#include <pdd/sizing/background_mesh.hpp>
#include <pdd/sizing/expression.hpp>
#include <pdd/sizing/grid.hpp>
#include <pdd/sizing/inverse_area_integral.hpp>
#include <pdd/sizing/min_sizing.hpp>
#include <pdd/sizing/regional.hpp>
#include <pdd/sizing/uniform.hpp>

#include "mesh_compare.hpp"
#include "test_support.hpp"
#include "verified.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace graded_meshing_test {
namespace {

using pdd::point;
constexpr double inf = std::numeric_limits<double>::infinity();

pdd::pslg unit_square() {
  pdd::pslg g;
  g.add_loop(std::vector<point>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 1);
  return g;
}

/// pdd::verify against min(criteria.max_area, F) with shielded triangles exempt from the
/// angle check; also checks the smallest unshielded angle. Returns the report.
pdd::verification_report expect_graded_verified(const pdd::triangle_mesh& m, const pdd::pslg& d,
                                                const pdd::generate_options& o,
                                                const std::string& at) {
  pdd::verify_options vo{.criteria = o.criteria};
  vo.quality_exempt = pdd::find_shielded_triangles(m, d);
  const pdd::verification_report rep = pdd::verify(m, d, vo, o.sizing);
  EXPECT_TRUE(rep.ok()) << at << ": " << pdd::test::describe(rep);
  EXPECT_EQ(rep.delaunay_violations, 0u) << at;
  EXPECT_EQ(rep.area_violations, 0u) << at;
  EXPECT_GE(pdd::compute_shielding_statistics(m, d).min_angle_unshielded_deg, 20.7 - 1e-9) << at;
  return rep;
}

// Outer square [0,4]^2, a hole [1,3]^2 (hole point (1.2, 1.2), in the ring between the hole's
// loop and the island) and an island [1.5,2.5]^2 inside the hole.
pdd::pslg nested_squares() {
  pdd::pslg g;
  const auto square = [&](double lo, double hi) {
    g.add_loop(std::vector<point>{{lo, lo}, {hi, lo}, {hi, hi}, {lo, hi}}, 1);
  };
  square(0, 4);
  square(1, 3);
  square(1.5, 2.5);
  g.holes.push_back({1.2, 1.2});
  return g;
}

TEST(RegionalSizing, EachRegionBoundsItsFace) {
  pdd::pslg g = nested_squares();
  g.regions.push_back({{0.5, 0.5}, 0.0, 0.01});
  g.regions.push_back({{3.5, 0.2}, 0.0, 0.03}); // same face: the smaller bound wins
  g.regions.push_back({{2, 2}, 7.0, 0.02});     // the island
  g.regions.push_back({{1.2, 1.3}, 5.0, -1});   // attribute only (in the hole): no bound
  const pdd::regional_sizing f(g);
  EXPECT_EQ(f.bounded_regions(), 3u);
  EXPECT_EQ(f.area_at({0.5, 3.5}), 0.01);
  EXPECT_EQ(f.area_at({3.9, 3.9}), 0.01);
  EXPECT_EQ(f.area_at({2.1, 2.4}), 0.02);
  EXPECT_EQ(f.area_at({1.2, 1.2}), inf); // in the hole
  EXPECT_EQ(f.area_at({5, 5}), inf);     // outside
  EXPECT_EQ(f.range(pdd::bbox{1.6, 1.6, 2.4, 2.4}).lo, 0.02);
  EXPECT_EQ(f.range(pdd::bbox{0, 0, 4, 4}).lo, 0.01);
}

TEST(RegionalSizing, RegionOutsideTheDomainOrOnItsBoundaryIsNamed) {
  for (const point p : {point{1.2, 1.2}, point{5, 5}, point{0, 2}, point{1, 1}}) {
    pdd::pslg g = nested_squares();
    g.regions.push_back({{0.5, 0.5}, 0.0, 0.01});
    g.regions.push_back({p, 0.0, 0.02});
    try {
      pdd::regional_sizing f(g);
      ADD_FAILURE() << p.x << " " << p.y << " accepted";
    } catch (const pdd::geometry_error& e) {
      EXPECT_NE(std::string(e.what()).find("region 1"), std::string::npos) << e.what();
      EXPECT_EQ(e.ids(), std::vector<std::size_t>{1});
    }
  }
}

// Triangle 1.6: `triangle -pq20.7Aa square.poly` with one region (0.5, 0.5) of area 1e-4
// gives 15602 triangles; CGAL's kernel makes 1.5-2% fewer at the same bound (DESIGN.md), the
// native kernel (a permissive build's default) about 1% more.
#ifdef PDD_PERMISSIVE
constexpr double whole_domain_ratio_bound = 1.02;
#else
constexpr double whole_domain_ratio_bound = 1.0;
#endif
TEST(RegionalSizing, SquareMatchesTriangleCount) {
  pdd::pslg g = unit_square();
  g.regions.push_back({{0.5, 0.5}, 0.0, 1e-4});
  pdd::generate_options o;
  o.sizing = pdd::regional_sizing(g);
  o.threads = 1;
  for (const std::size_t n : {1u, 16u}) {
    o.subdomains = n;
    const pdd::generate_result r = pdd::generate(g, o);
    const double ratio = static_cast<double>(r.mesh.triangles.size()) / 15602.0;
    EXPECT_GT(ratio, 0.96) << "N " << n << ": " << r.mesh.triangles.size();
    EXPECT_LT(ratio, n == 1 ? whole_domain_ratio_bound : 1.06)
        << "N " << n << ": " << r.mesh.triangles.size();
    expect_graded_verified(r.mesh, g, o, "square N " + std::to_string(n));
  }
}

// Triangle 1.6 on the letter A with one region (0.28, -0.785) of area 1e-5: 13070 triangles.
TEST(RegionalSizing, LetterAMatchesTriangleCount) {
  const auto dir = pdd::test::shared_data_dir();
  if (dir.empty() || !std::filesystem::exists(dir / "triangle_A.poly"))
    GTEST_SKIP() << "../shared/data/triangle_A.poly is absent";
  pdd::pslg g = pdd::read_poly(dir / "triangle_A.poly");
  ASSERT_TRUE(g.regions.empty());
  g.regions.push_back({{0.28, -0.785}, 0.0, 1e-5});
  pdd::generate_options o;
  o.sizing = pdd::regional_sizing(g);
  o.subdomains = 1;
  const pdd::generate_result r = pdd::generate(g, o);
  const double ratio = static_cast<double>(r.mesh.triangles.size()) / 13070.0;
  EXPECT_GT(ratio, 0.96) << r.mesh.triangles.size();
  EXPECT_LT(ratio, whole_domain_ratio_bound) << r.mesh.triangles.size();
  expect_graded_verified(r.mesh, g, o, "A");
}

/// Fields over a domain's bounding box b: a grid and a background mesh, both growing from
/// `fine` at the lower left to 8 x fine at the upper right.
pdd::any_sizing grid_field(const pdd::bbox& b, double fine) {
  std::vector<double> v;
  for (int j = 0; j < 9; ++j)
    for (int i = 0; i < 9; ++i)
      v.push_back(fine * (1 + 3.5 * (i + j) / 8.0));
  return pdd::grid_sizing({b.xmin, b.ymin}, b.width() / 8, b.height() / 8, 9, 9, v);
}
pdd::any_sizing background_field(const pdd::bbox& b, double fine) {
  const point c{(b.xmin + b.xmax) / 2, (b.ymin + b.ymax) / 2};
  return pdd::background_mesh_sizing(
      {{b.xmin, b.ymin}, {b.xmax, b.ymin}, {b.xmax, b.ymax}, {b.xmin, b.ymax}, c},
      {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}}, {8 * fine, 8 * fine, 8 * fine, 8 * fine, fine},
      pdd::background_mesh_sizing::interpolation::per_vertex);
}

TEST(GradedMeshing, BundledDomainsVerifiedAndThreadIndependent) {
  struct named {
    const char* name;
    pdd::pslg domain;
  };
  const std::vector<named> domains{{"key", pdd::key_domain()}, {"pipe", pdd::pipe_domain()}};
  for (const named& dn : domains) {
    const pdd::bbox b = pdd::bounding_box(dn.domain);
    const double fine = b.width() * b.height() / 20000.0;
    const std::vector<std::pair<std::string, pdd::any_sizing>> fields{
        {"expression",
         pdd::expression_sizing(std::to_string(fine) + "*(1+30*((x-" + std::to_string(b.xmin) +
                                ")/" + std::to_string(b.width()) + ")^2)")},
        {"grid", grid_field(b, fine)},
        {"background", background_field(b, fine)}};
    for (const auto& nf : fields) {
      for (const std::size_t n : {1u, 16u}) {
        const std::string at = std::string(dn.name) + " " + nf.first + " N " + std::to_string(n);
        SCOPED_TRACE(at);
        pdd::generate_options o;
        o.sizing = nf.second;
        o.subdomains = n;
        o.threads = 1;
        const pdd::generate_result one = pdd::generate(dn.domain, o);
        EXPECT_EQ(one.statistics.interface_splits, 0u);
        EXPECT_GT(one.mesh.triangles.size(), 2000u);
        expect_graded_verified(one.mesh, dn.domain, o, at);
        o.threads = 2;
        EXPECT_TRUE(pdd::test::bitwise_equal(one.mesh, pdd::generate(dn.domain, o).mesh));
      }
    }
  }
}

TEST(GradedMeshing, MaxAreaAndFieldCombine) {
  const pdd::pslg g = unit_square();
  pdd::generate_options o;
  o.sizing = pdd::expression_sizing("1e-3*(1+9*x)");
  o.criteria.max_area = 2e-3; // caps the coarse side (F up to 1e-2)
  o.subdomains = 4;
  const pdd::generate_result r = pdd::generate(g, o);
  expect_graded_verified(r.mesh, g, o, "combined");
  // the mesh is graded: its triangles near x = 0 are much smaller than near x = 1
  double left = 0, right = 0;
  for (const auto& t : r.mesh.triangles) {
    const point &a = r.mesh.vertices[t[0]], &b = r.mesh.vertices[t[1]], &c = r.mesh.vertices[t[2]];
    const double area = std::abs((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y)) / 2;
    const double cx = (a.x + b.x + c.x) / 3;
    if (cx < 0.1) left = std::max(left, area);
    if (cx > 0.9) right = std::max(right, area);
  }
  EXPECT_LE(left, 1e-3 * 1.9);
  EXPECT_GT(right, 1e-3 * 1.9);
  EXPECT_LE(right, 2e-3);
}

TEST(GradedMeshing, VerifyReportsTrianglesAboveTheField) {
  const pdd::pslg g = unit_square();
  pdd::generate_options o;
  o.sizing = pdd::expression_sizing("1e-3*(1+9*x)");
  o.subdomains = 1;
  const pdd::generate_result r = pdd::generate(g, o);
  pdd::verify_options vo{.criteria = o.criteria};
  // a field 4 times finer on the right half: the mesh violates it there only
  const pdd::expression_sizing finer("x < 0.5 ? 1e-3*(1+9*x) : 0.25e-3*(1+9*x)");
  const pdd::verification_report rep = pdd::verify(r.mesh, g, vo, finer);
  EXPECT_GT(rep.area_violations, 10u);
  EXPECT_FALSE(rep.ok());
  EXPECT_EQ(pdd::verify(r.mesh, g, vo, o.sizing).area_violations, 0u);
}

// Theorem 22 on Algorithm 7.1's decomposition: every separator is split with its smaller k,
// relation 7.1 holds everywhere (k lowered where needed), the mesh is verified and thread-
// independent; a field graded 1000-fold no longer falls back to the uniform path, and its
// over-refinement against the monolithic mesh is far below the interim path's (forced by a
// k_scale below 1, which keeps the fallback for that case).
TEST(GradedPath, KPerSubdomainOnGradationControlledDecomposition) {
  const pdd::pslg d = pdd::pipe_domain();
  const pdd::bbox b = pdd::bounding_box(d);
  const double fine = b.width() * b.height() / 40000.0;
  const std::string x = "((x-" + std::to_string(b.xmin) + ")/" + std::to_string(b.width()) + ")";
  pdd::generate_options o;
  o.sizing = pdd::expression_sizing(std::to_string(fine) + "*(1+2*" + x + ")");
  o.subdomains = 16;
  o.threads = 1;
  const pdd::generate_result graded = pdd::generate(d, o);
  const pdd::generate_statistics& st = graded.statistics;
  ASSERT_TRUE(st.graded_path) << st.graded_fallback;
  EXPECT_TRUE(st.gradation_controlled);
  EXPECT_GE(st.subdomains, 16u); // at least the N asked for
  ASSERT_EQ(st.subdomain_k.size(), st.subdomains);
  EXPECT_LT(st.k_ratio_max, std::numbers::sqrt3);
  EXPECT_GT(st.k_ratio_max, 1.05); // the k_i differ
  EXPECT_EQ(st.k, *std::min_element(st.subdomain_k.begin(), st.subdomain_k.end()));
  EXPECT_EQ(st.interface_splits, 0u);
  expect_graded_verified(graded.mesh, d, o, "graded path");
  o.threads = 2;
  EXPECT_TRUE(pdd::test::bitwise_equal(graded.mesh, pdd::generate(d, o).mesh));
  // gradation 1000 across the pipe (about 110K triangles)
  o.sizing = pdd::expression_sizing(std::to_string(fine / 100) + "*(1+999*" + x + "^2)");
  const pdd::generate_result steep = pdd::generate(d, o);
  EXPECT_TRUE(steep.statistics.graded_path) << steep.statistics.graded_fallback;
  EXPECT_LT(steep.statistics.k_ratio_max, std::numbers::sqrt3);
  EXPECT_EQ(steep.statistics.interface_splits, 0u);
  expect_graded_verified(steep.mesh, d, o, "steep field");
  o.decoupling.k_scale = std::nextafter(1.0, 0.0);
  const pdd::generate_result interim = pdd::generate(d, o);
  EXPECT_FALSE(interim.statistics.graded_path);
  EXPECT_FALSE(interim.statistics.graded_fallback.empty());
  expect_graded_verified(interim.mesh, d, o, "interim path");
  o.decoupling.k_scale = 1.0;
  o.subdomains = 1;
  const auto mono = static_cast<double>(pdd::generate(d, o).mesh.triangles.size());
  const auto over = [&](const pdd::generate_result& r) {
    return static_cast<double>(r.mesh.triangles.size()) / mono - 1.0;
  };
  EXPECT_LT(over(steep), 0.12) << steep.mesh.triangles.size() << " vs " << mono << ", N "
                               << steep.statistics.subdomains << ", lowered k "
                               << steep.statistics.lowered_k << ", interim "
                               << interim.mesh.triangles.size();
  EXPECT_GT(over(interim), 2 * over(steep)) << interim.mesh.triangles.size();
  RecordProperty("over_refinement_graded_pct", std::to_string(100 * over(steep)));
  RecordProperty("over_refinement_interim_pct", std::to_string(100 * over(interim)));
}

TEST(InverseAreaIntegral, MatchesTheClosedForm) {
  // integral over [0,1]^2 of 1 / (1e-3 (1 + x)) = 1000 ln 2
  const pdd::expression_sizing f("1e-3*(1+x)");
  const double i = pdd::inverse_area_integral(unit_square(), inf, f);
  EXPECT_NEAR(i, 1000 * std::numbers::ln2, 1e-3 * 1000 * std::numbers::ln2);
  // capped by max_area 1.5e-3 where F is larger: 1000 (ln 1.5 + 0.5 / 1.5)
  const double capped = pdd::inverse_area_integral(unit_square(), 1.5e-3, f);
  EXPECT_NEAR(capped, 1000 * (std::log(1.5) + 0.5 / 1.5), 2e-3 * capped);
  EXPECT_EQ(pdd::inverse_area_integral(unit_square(), inf, pdd::uniform_sizing{}), 0.0);
}

} // namespace

} // namespace graded_meshing_test
