// Angle bounds above Ruppert's (20.7 deg, pdd::within_ruppert_bound): the shields (Theorem 24)
// and the decoupling path among them are proven up to it only, and above it the kernels split
// both (Triangle's Texas at 31-33 deg: a shield edge split by the native kernel, CGAL's kernel
// refining without end beside a shield). A domain of closed loops with an input angle below
// 60 deg is then meshed whole and unshielded, the kernel's own small-angle rule meshing the
// corner and pdd::quality_exemptions exempting what that rule leaves; a domain without such an
// angle is decoupled as below the bound; the geometric path is not planned above it.
#include <pdd/generate.hpp>
#include <pdd/kernels/native/mesher.hpp>
#include <pdd/mesh/verify.hpp>
#include <pdd/pipeline/run_plan.hpp>

#include <gtest/gtest.h>

#include "test_domains.hpp"

#include <cmath>
#include <numbers>
#include <string>

namespace ruppert_bound_test {
namespace {

/// A right triangle with a 15 deg corner at the origin, and a square hole.
pdd::pslg spike() {
  pdd::pslg g;
  const double h = 2.0 * std::tan(15.0 * std::numbers::pi / 180.0);
  g.vertices = {{0, 0}, {2, 0}, {2, h}, {1.5, 0.1}, {1.8, 0.1}, {1.8, 0.3}, {1.5, 0.3}};
  g.segments = {{0, 1, 1}, {1, 2, 1}, {2, 0, 1}, {3, 4, 2}, {4, 5, 2}, {5, 6, 2}, {6, 3, 2}};
  g.vertex_markers.assign(g.vertices.size(), 0);
  g.holes = {{1.65, 0.2}};
  return g;
}

pdd::generate_options options(double min_angle, std::size_t n) {
  pdd::generate_options o;
  o.criteria.min_angle_deg = min_angle;
  o.criteria.max_area = 2e-4;
  o.subdomains = n;
  o.threads = 2;
  return o;
}

/// pdd::verify with its default exemptions (pdd-mesh --verify's verdict) passes.
void expect_verified(const pdd::triangle_mesh& m, const pdd::pslg& g, const pdd::mesh_criteria& c) {
  const pdd::verification_report rep = pdd::verify(m, g, {.criteria = c});
  EXPECT_TRUE(rep.ok()) << (rep.messages.empty() ? std::string() : rep.messages.front());
}

TEST(RuppertBound, TheBoundIsRuppertsRatioSqrt2) {
  EXPECT_TRUE(pdd::within_ruppert_bound(20.7));
  EXPECT_TRUE(pdd::within_ruppert_bound(pdd::min_angle_for_ratio(std::numbers::sqrt2)));
  EXPECT_FALSE(pdd::within_ruppert_bound(20.71));
  EXPECT_FALSE(pdd::within_ruppert_bound(33.0));
  EXPECT_TRUE(pdd::mesh_criteria{}.within_ruppert_bound()) << "the default angle bound";
}

TEST(RuppertBound, AboveItSmallInputAnglesAreMeshedWholeAndUnshielded) {
  const pdd::pslg g = spike();
  const pdd::run_plan plan = pdd::plan_run(g, options(30.0, 4), 2).plan;
  EXPECT_EQ(plan.path, pdd::mesh_path::monolithic);
  EXPECT_EQ(plan.subdomains, 1u);
  EXPECT_NE(plan.reason.find("above Ruppert's 20.7 deg"), std::string::npos) << plan.reason;
  EXPECT_NE(plan.reason.find("at vertex 0"), std::string::npos) << plan.reason;
  for (const double angle : {25.0, 30.0}) {
    SCOPED_TRACE(angle);
    const pdd::generate_result r = pdd::generate(g, options(angle, 4));
    EXPECT_EQ(r.statistics.subdomains, 1u);
    EXPECT_EQ(r.statistics.shielded_triangles, 0u) << "unshielded: Theorem 24 needs 20.7 deg";
    expect_verified(r.mesh, g, options(angle, 4).criteria);
  }
  for (const double angle : {30.0, 33.0}) {
    SCOPED_TRACE(angle);
    const pdd::generate_result r = pdd::generate<pdd::native::mesher>(g, options(angle, 4));
    EXPECT_EQ(r.statistics.shielded_triangles, 0u);
    expect_verified(r.mesh, g, options(angle, 4).criteria);
  }
}

TEST(RuppertBound, AtItTheSameDomainIsDecoupledWithShields) {
  const pdd::pslg g = spike();
  const pdd::generate_result r = pdd::generate(g, options(20.7, 4));
  EXPECT_EQ(r.statistics.subdomains, 4u);
  EXPECT_GT(r.statistics.shielded_triangles, 0u);
  expect_verified(r.mesh, g, options(20.7, 4).criteria);
}

TEST(RuppertBound, AboveItAGeneralDomainWithSmallAnglesBetweenSegmentsIsMeshedWhole) {
  pdd::pslg g = pdd::test::unit_square(); // and its diagonal: 45 deg between segments
  g.segments.push_back({0, 2, 3});
  const pdd::run_plan above = pdd::plan_run(g, options(30.0, 4), 2).plan;
  EXPECT_EQ(above.subdomains, 1u);
  EXPECT_NE(above.reason.find("above Ruppert's 20.7 deg"), std::string::npos) << above.reason;
  const pdd::generate_result r = pdd::generate(g, options(30.0, 4));
  EXPECT_EQ(r.statistics.subdomains, 1u);
  expect_verified(r.mesh, g, options(30.0, 4).criteria);
  EXPECT_GE(pdd::plan_run(g, options(20.7, 4), 2).plan.subdomains, 4u) << "decoupled at 20.7";
}

TEST(RuppertBound, AboveItADomainWithoutSmallAnglesIsDecoupledAndNotGeometric) {
  const pdd::pslg square = pdd::test::unit_square();
  pdd::generate_options o = options(30.0, 8);
  o.criteria.max_area = 1e-4;
  const pdd::run_plan graded = pdd::plan_run(square, o, 2).plan;
  EXPECT_EQ(graded.path, pdd::mesh_path::graded);
  EXPECT_EQ(graded.subdomains, 8u);
  o.geometric_sizing = pdd::geometric_sizing_mode::on;
  const pdd::run_plan not_geometric = pdd::plan_run(square, o, 2).plan;
  EXPECT_EQ(not_geometric.path, pdd::mesh_path::graded);
  EXPECT_NE(not_geometric.reason.find("above 20.7 deg"), std::string::npos) << not_geometric.reason;
  o.criteria.min_angle_deg = 20.7;
  EXPECT_EQ(pdd::plan_run(square, o, 2).plan.path, pdd::mesh_path::geometric);
}

} // namespace
} // namespace ruppert_bound_test
