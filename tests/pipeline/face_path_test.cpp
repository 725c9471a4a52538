// The geometric path on a domain that is not one of closed loops (issue 36 item 1): a layer that
// thins out to a tiny gap held k_i of its whole face (and, by relation 7.1, of its neighbours)
// at that gap, so MADD from the faces cut every interface into tiny pieces; the decomposition
// is now graded towards the faces' tiny features. Asserted on a generated wedge (the geometry of
// benchmarks/run_layered.sh): the path taken and why, a verified conforming mesh with the
// domain's area, far fewer triangles than MADD from the faces alone, and the automatic plan's
// fallback to the whole domain when the estimate says decoupling would add too much.
#include <pdd/generate.hpp>
#include <pdd/mesh/verify.hpp>
#include <pdd/pipeline/detail/face_path.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace face_path_test {
namespace {

/// A 20 x 4 section: the top layer between y = 0 and (0, -0.5) - (10, -0.01) - (10.5, 0) thins
/// from 0.5 to 0.01 and ends at 1.1 deg on the top side (a cap); one interface (0, -2) -
/// (20, -2.5) below. Three faces, none a hole.
pdd::pslg thinning_wedge() {
  pdd::pslg g;
  for (const pdd::point p : std::vector<pdd::point>{{0, 0},
                                                    {10.5, 0},
                                                    {20, 0},
                                                    {20, -2.5},
                                                    {20, -4},
                                                    {0, -4},
                                                    {0, -2},
                                                    {0, -0.5},
                                                    {10, -0.01}})
    g.add_vertex(p);
  for (const auto& [a, b] : std::vector<std::pair<pdd::index_t, pdd::index_t>>{
           {0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 5}, {5, 6}, {6, 7}, {7, 0}, {7, 8}, {8, 1}, {6, 3}})
    g.add_segment(a, b);
  return g;
}

pdd::generate_options options(double max_area, std::size_t subdomains) {
  pdd::generate_options o;
  o.criteria.min_angle_deg = 20.7;
  o.criteria.max_area = max_area;
  o.subdomains = subdomains;
  o.threads = 2;
  o.geometric_sizing = pdd::geometric_sizing_mode::on; // at every size (auto: from 20K)
  return o;
}

void expect_verified(const pdd::generate_result& r, const pdd::pslg& g, double max_area) {
  pdd::verify_options vo;
  vo.criteria.min_angle_deg = 20.7;
  vo.criteria.max_area = max_area;
  pdd::pslg d = g;
  d.rule = pdd::domain_rule::triangle;
  const pdd::verification_report rep = pdd::verify(r.mesh, d, vo);
  EXPECT_TRUE(rep.ok()) << "delaunay " << rep.delaunay_violations << " missing "
                        << rep.missing_segments << " quality " << rep.quality_violations << " area "
                        << rep.area_violations << " mesh area " << rep.area_mesh;
  EXPECT_NEAR(rep.area_mesh, 80.0, 80.0 * 1e-9);
}

TEST(FacePath, AThinningLayerIsGradedTowardsItsTipInsteadOfSettingKForItsFace) {
  const pdd::pslg g = thinning_wedge();
  const double max_area = 0.003;
  const pdd::generate_result whole = pdd::generate(g, options(max_area, 1));
  const pdd::generate_result graded = pdd::generate(g, options(max_area, 4));
  pdd::generate_options off = options(max_area, 4);
  off.geometric_sizing = pdd::geometric_sizing_mode::off;
  const pdd::generate_result faces = pdd::generate(g, off);
  EXPECT_EQ(graded.statistics.path, "geometric");
  EXPECT_NE(graded.statistics.plan_reason.find("geometric path on the faces"), std::string::npos)
      << graded.statistics.plan_reason;
  EXPECT_GT(graded.statistics.sizing_round_used, 0u); // a round graded towards the tip
  EXPECT_GT(graded.statistics.subdomains, 4u);
  EXPECT_EQ(faces.statistics.path, "graded");
  expect_verified(graded, g, max_area);
  expect_verified(faces, g, max_area);
  const auto count = [](const pdd::generate_result& r) {
    return static_cast<double>(r.mesh.triangles.size());
  };
  // measured: whole 41,085, graded 49,563 (+21 %), MADD from the faces 95,589 (+133 %)
  EXPECT_LT(count(graded), 1.3 * count(whole));
  EXPECT_LT(count(graded), 0.7 * count(faces));
}

TEST(FacePath, AutomaticNFallsBackToTheWholeDomainWhenTheEstimateExceedsTheBound) {
  const pdd::pslg g = thinning_wedge();
  const double max_area = 0.001; // estimated 7,624 more of 121,951: 6.3 % > 3 %
  const pdd::generate_result automatic = pdd::generate(g, options(max_area, 0));
  EXPECT_EQ(automatic.statistics.path, "monolithic");
  EXPECT_NE(automatic.statistics.plan_reason.find("planning.max_face_over_refinement"),
            std::string::npos)
      << automatic.statistics.plan_reason;
  pdd::generate_options loose = options(max_area, 0);
  loose.planning.max_face_over_refinement = 0.2;
  const pdd::generate_result decoupled = pdd::generate(g, loose);
  EXPECT_EQ(decoupled.statistics.path, "geometric") << decoupled.statistics.plan_reason;
  EXPECT_GT(decoupled.statistics.subdomains, 1u);
  expect_verified(decoupled, g, max_area);
  EXPECT_GT(decoupled.mesh.triangles.size(), automatic.mesh.triangles.size());
}

// Automatic N compares the estimate times planning.face_over_refinement_margin with the bound:
// the wedge at 0.001 is estimated to add 8,187 triangles of 121,951, so with a bound of 8 % (9,756)
// the margin 1.35 (11,052) meshes it whole and a margin of 1 decouples.
TEST(FacePath, AutomaticNKeepsAMarginOnTheEstimate) {
  const pdd::pslg g = thinning_wedge();
  pdd::generate_options o = options(0.001, 0);
  o.planning.max_face_over_refinement = 0.08;
  const pdd::generate_result kept = pdd::generate(g, o);
  EXPECT_EQ(kept.statistics.path, "monolithic") << kept.statistics.plan_reason;
  EXPECT_NE(kept.statistics.plan_reason.find("face_over_refinement_margin"), std::string::npos)
      << kept.statistics.plan_reason;
  o.planning.face_over_refinement_margin = 1.0;
  const pdd::generate_result decoupled = pdd::generate(g, o);
  EXPECT_EQ(decoupled.statistics.path, "geometric") << decoupled.statistics.plan_reason;
  expect_verified(decoupled, g, 0.001);
}

// Geometric sizing auto plans the path for a requested N from planning.min_face_path_triangles
// estimated triangles (the wedge at 0.003: about 41K) when a feature of a face is smaller than the
// mesh, and leaves MADD from the faces below it: its rounds cost more than they save there.
TEST(FacePath, GeometricSizingAutoPlansItForARequestedNFromTheSizeWhereItPays) {
  const pdd::pslg g = thinning_wedge();
  pdd::generate_options o = options(0.003, 4);
  o.geometric_sizing = pdd::geometric_sizing_mode::automatic;
  const pdd::generate_result planned = pdd::generate(g, o);
  EXPECT_EQ(planned.statistics.path, "geometric") << planned.statistics.plan_reason;
  EXPECT_NE(planned.statistics.plan_reason.find("of the faces smaller than the mesh"),
            std::string::npos)
      << planned.statistics.plan_reason;
  expect_verified(planned, g, 0.003);
  o.planning.min_face_path_triangles = 1e6;
  const pdd::generate_result faces = pdd::generate(g, o);
  EXPECT_EQ(faces.statistics.path, "graded") << faces.statistics.plan_reason;
  EXPECT_NE(faces.statistics.plan_reason.find("planning.min_face_path_triangles"),
            std::string::npos)
      << faces.statistics.plan_reason;
  EXPECT_LT(planned.mesh.triangles.size(), 0.7 * faces.mesh.triangles.size());
}

// Above Ruppert's bound the kernels split the path beside the small subdomains this path makes
// (la.poly at 28-30 deg ran out of invariance repairs): MADD from the faces, as before.
TEST(FacePath, AboveRuppertsAngleBoundAThinningLayerIsMeshedWhole) {
  // its 1.1 deg tip is an angle between segments below 60 deg (tests/pipeline/ruppert_bound_test)
  const pdd::pslg g = thinning_wedge();
  pdd::generate_options o = options(0.003, 4);
  o.criteria.min_angle_deg = 30.0;
  const pdd::generate_result r = pdd::generate(g, o);
  EXPECT_EQ(r.statistics.path, "monolithic");
  EXPECT_EQ(r.statistics.subdomains, 1u);
  EXPECT_NE(r.statistics.plan_reason.find("above Ruppert's 20.7 deg"), std::string::npos)
      << r.statistics.plan_reason;
  pdd::verify_options vo;
  vo.criteria = o.criteria;
  pdd::pslg d = g;
  d.rule = pdd::domain_rule::triangle;
  EXPECT_TRUE(pdd::verify(r.mesh, d, vo).ok());
}

// A fuzz finding (tests/fuzz, seed 1): a square with three wedges at pinch vertices, holes
// between; at --subdomains 2 Algorithm 7.1 could not measure a subdomain whose loops touch at a
// vertex and generate() refused a valid input ("duplicate vertices 1 and 4"). The rounds now
// stop there, the reason says so, and MADD's own decomposition meshes.
TEST(FacePath, APinchedFaceStopsTheRoundsInsteadOfRefusingTheInput) {
  pdd::pslg g;
  for (const pdd::point p : std::vector<pdd::point>{{0, 0},
                                                    {5, 0},
                                                    {10, 0},
                                                    {10, 10},
                                                    {0, 10},
                                                    {6.455443589413995, 0.3628828433995016},
                                                    {6.060660171779821, 1.0606601717798212},
                                                    {5, 6},
                                                    {6.969615506024416, 6.347296355333861},
                                                    {6.147152872702092, 7.638304088577984},
                                                    {5.5176380902050415, 7.931851652578136},
                                                    {4, 7.732050807568878},
                                                    {3.1873844259267, 6.8452365234813985},
                                                    {3.120614758428183, 5.315959713348663},
                                                    {4.000001811150368, 4.120614758428184},
                                                    {5.845236523481399, 4.1873844259267}})
    g.add_vertex(p);
  for (const auto& [a, b] : std::vector<std::pair<pdd::index_t, pdd::index_t>>{
           {0, 1},  {1, 2},   {2, 3},  {3, 4},  {4, 0},   {1, 5},   {5, 6},
           {6, 1},  {7, 8},   {8, 9},  {9, 7},  {7, 10},  {10, 11}, {11, 7},
           {7, 12}, {12, 13}, {13, 7}, {7, 14}, {14, 15}, {15, 7}})
    g.add_segment(a, b);
  g.holes = {{5.838701253731273, 0.4745143383931076},
             {6.038922792908836, 6.661866814637281},
             {4.8392126967350135, 7.4745143383931076},
             {6.038922792908836, 6.66182078943354},
             {5.053732078943354, 4.769333061451628}};
  const pdd::generate_result r = pdd::generate(g, options(100.0 / 420.37, 2));
  EXPECT_EQ(r.statistics.path, "geometric");
  EXPECT_NE(r.statistics.plan_reason.find("no further round: Algorithm 7.1 stopped"),
            std::string::npos)
      << r.statistics.plan_reason;
  EXPECT_TRUE(pdd::verify(r.mesh, g).ok());
}

// The cost rule ranks pieces by how much shorter than the mesh they are: none for an edge left
// whole, sqrt(h / l) per split point, at least 1 per point.
TEST(FacePath, APieceMuchShorterThanTheMeshCostsMore) {
  pdd::decoupled_decomposition dd;
  dd.parts.vertices = {{0, 0}, {1, 0}};
  pdd::path_edge e;
  e.u = 0;
  e.v = 1;
  e.length = 1.0;
  e.pieces = 1;
  const double area = 0.01; // h = sqrt(4 a / sqrt 3) = 0.152
  EXPECT_EQ(pdd::detail::path_edge_cost(dd, e, {}, area), 0.0);
  e.pieces = 100; // pieces of 0.01: 99 points, sqrt(15.2) each
  const double h = std::sqrt(4.0 * area / std::sqrt(3.0));
  EXPECT_NEAR(pdd::detail::path_edge_cost(dd, e, {}, area), 0.8 * 99 * std::sqrt(h / 0.01), 1e-9);
  e.pieces = 4; // pieces of 0.25, longer than h: 1 per point
  EXPECT_NEAR(pdd::detail::path_edge_cost(dd, e, {}, area), 0.8 * 3, 1e-12);
}

} // namespace
} // namespace face_path_test
