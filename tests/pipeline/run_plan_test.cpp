// The plan of a run (issue 34 item 1): pdd::plan_run decides the path, N and the reason once,
// from the domain and the options; fallbacks and the geometric retry are plans that
// pdd::whole_domain_plan and pdd::plan_after_path return; the pipeline never rewrites the
// caller's options (the geometric path's F is the chain's mesh field, not options().sizing).
#include <pdd/pipeline.hpp>
#include <pdd/pipeline/run_plan.hpp>
#include <pdd/sizing/any_sizing.hpp>
#include <pdd/sizing/expression.hpp>

#include <gtest/gtest.h>

#include "test_domains.hpp"

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace run_plan_test {
namespace {

using pdd::point;

using pdd::test::notched_square;
using pdd::test::unit_square;

/// A plan of N = 8 on `path` under automatic N, as plan_run would make it.
pdd::run_plan automatic_plan(pdd::mesh_path path) {
  pdd::run_plan p;
  p.path = path;
  p.subdomains = 8;
  p.automatic = true;
  return p;
}

pdd::generate_options bounded(double max_area, std::size_t n = 0) {
  pdd::generate_options o;
  o.criteria.max_area = max_area;
  o.subdomains = n;
  o.threads = 1;
  return o;
}

TEST(PlanRun, ThePathFollowsTheOptions) {
  const pdd::pslg g = unit_square();
  const pdd::run_plan one = pdd::plan_run(g, bounded(1e-4, 1), 1).plan;
  EXPECT_EQ(one.path, pdd::mesh_path::monolithic);
  EXPECT_EQ(one.subdomains, 1u);
  EXPECT_EQ(one.reason, "one subdomain requested");
  EXPECT_FALSE(one.automatic);

  const pdd::run_plan graded = pdd::plan_run(g, bounded(1e-4, 8), 1).plan;
  EXPECT_EQ(graded.path, pdd::mesh_path::graded);
  EXPECT_EQ(graded.subdomains, 8u);
  EXPECT_FALSE(graded.gradation_controlled) << "no field: N-way MADD";
  EXPECT_GT(graded.estimate.triangles, 1e4);
  EXPECT_DOUBLE_EQ(graded.area, 1.0);

  pdd::generate_options k = bounded(1e-4, 8);
  k.decoupling.k_scale = 0.5;
  EXPECT_EQ(pdd::plan_run(g, k, 1).plan.path, pdd::mesh_path::uniform);

  pdd::generate_options field = bounded(1e-4, 8);
  field.sizing = pdd::expression_sizing("1e-5+1e-4*x");
  const pdd::run_plan f = pdd::plan_run(g, field, 1).plan;
  EXPECT_EQ(f.path, pdd::mesh_path::graded);
  EXPECT_TRUE(f.gradation_controlled) << "a field: Algorithm 7.1";
  EXPECT_LE(f.decoupling_criteria.max_area, 1e-5 * (1 + 1e-9)) << "the field's minimum";

  pdd::generate_options on = bounded(1e-4, 8);
  on.geometric_sizing = pdd::geometric_sizing_mode::on;
  const pdd::run_plan geo = pdd::plan_run(g, on, 1).plan;
  EXPECT_EQ(geo.path, pdd::mesh_path::geometric);
  EXPECT_EQ(geo.reason, "geometric sizing on");
  EXPECT_EQ(geo.geometric_cap, on.geometric_loop.max_subdomains);
}

TEST(PlanRun, AutomaticNAndTheGeneralDomain) {
  const pdd::run_plan autoplan = pdd::plan_run(notched_square(), bounded(5e-6), 1).plan;
  EXPECT_TRUE(autoplan.automatic);
  EXPECT_GT(autoplan.subdomains, 1u);
  EXPECT_EQ(autoplan.path, pdd::mesh_path::geometric);
  EXPECT_NE(autoplan.reason.find("Algorithm 8.3"), std::string::npos) << autoplan.reason;

  pdd::pslg general = unit_square(); // a dangling segment: not one of closed loops
  general.add_segment(general.add_vertex({0.2, 0.5}), general.add_vertex({0.8, 0.5}));
  const pdd::planned_run r = pdd::plan_run(general, bounded(1e-3, 1), 1);
  EXPECT_TRUE(r.plan.general_domain);
  EXPECT_EQ(r.domain.rule, pdd::domain_rule::triangle) << "read by Triangle's rule";
  EXPECT_EQ(r.plan.path, pdd::mesh_path::monolithic);
  EXPECT_FALSE(r.regions) << "one subdomain asked for: no regions read";
}

TEST(PlanAfterPath, NothingWhenDecouplingPays) {
  pdd::run_plan p = automatic_plan(pdd::mesh_path::graded);
  const pdd::planning_options o; // 5 % of the estimate
  EXPECT_FALSE(pdd::plan_after_path(p, 50, 1000.0, 0, 8, "", o));
  p.automatic = false; // a requested N is kept whatever the split points
  EXPECT_FALSE(pdd::plan_after_path(p, 500, 1000.0, 0, 8, "", o));
}

TEST(PlanAfterPath, TheWholeDomainWhenItDoesNot) {
  pdd::run_plan p = automatic_plan(pdd::mesh_path::graded);
  p.reason = "planned";
  const std::optional<pdd::run_plan> next =
      pdd::plan_after_path(p, 51, 1000.0, 0, 8, "so far", pdd::planning_options{});
  ASSERT_TRUE(next);
  EXPECT_EQ(next->path, pdd::mesh_path::monolithic);
  EXPECT_EQ(next->subdomains, 1u);
  EXPECT_TRUE(next->fallback);
  EXPECT_EQ(next->reason.rfind("51 split points", 0), 0u) << next->reason;
  EXPECT_NE(next->reason.find("decoupling would not pay"), std::string::npos);
}

TEST(PlanAfterPath, TheGeometricLoopOnceMoreWithHalfItsCap) {
  pdd::run_plan p = automatic_plan(pdd::mesh_path::geometric);
  p.first_reason = "first";
  const pdd::planning_options o;
  std::optional<pdd::run_plan> retry = pdd::plan_after_path(p, 100, 1000.0, 256, 256, "now", o);
  ASSERT_TRUE(retry);
  EXPECT_EQ(retry->path, pdd::mesh_path::geometric);
  EXPECT_EQ(retry->geometric_cap, 128u);
  EXPECT_TRUE(retry->geometric_retried);
  EXPECT_EQ(retry->reason.rfind("first; 100 split points with the loop's cap of 256", 0), 0u)
      << retry->reason;
  // no third run: the whole domain, its reason extending the statistics' one
  const std::optional<pdd::run_plan> last =
      pdd::plan_after_path(*retry, 100, 1000.0, 128, 128, "now", o);
  ASSERT_TRUE(last);
  EXPECT_EQ(last->path, pdd::mesh_path::monolithic);
  EXPECT_EQ(last->reason.rfind("now; 100 split points", 0), 0u) << last->reason;
  // half the cap below 4N, or not binding on the subdomains made: the whole domain at once
  EXPECT_EQ(pdd::plan_after_path(p, 100, 1000.0, 60, 60, "now", o)->path,
            pdd::mesh_path::monolithic);
  EXPECT_EQ(pdd::plan_after_path(p, 100, 1000.0, 4096, 900, "now", o)->path,
            pdd::mesh_path::monolithic);
}

// The geometric path with Algorithm 8.3's F meshes with F, and the caller's options stay as
// given: before the plan value, the pipeline wrote F into options().sizing and the loop's
// smaller cap into options().geometric_loop.
TEST(Pipeline, NeverRewritesTheOptions) {
  pdd::generate_options o = bounded(5e-6);
  o.geometric_field = pdd::geometric_mesh_field::algorithm_8_3;
  o.max_geometric_over_refinement = 1e9;
  o.geometric_loop.max_subdomains = 256;
  o.planning.max_split_point_fraction = 0.0; // the retry with half the cap, then one subdomain
  pdd::pipeline<> p(notched_square(), o);
  p.decouple();
  EXPECT_EQ(p.statistics().geometric_cap, 128u) << p.statistics().plan_reason;
  EXPECT_EQ(p.plan().path, pdd::mesh_path::monolithic);
  EXPECT_TRUE(p.plan().fallback);
  EXPECT_FALSE(p.options().sizing);
  EXPECT_EQ(p.options().geometric_loop.max_subdomains, 256u);
  EXPECT_FALSE(p.meshing().sizing) << "the whole domain meshes with the user's field";

  o.planning.max_split_point_fraction = 1.0; // decoupling pays: meshed with F
  pdd::pipeline<> q(notched_square(), o);
  q.decouple();
  EXPECT_EQ(q.plan().path, pdd::mesh_path::geometric) << q.statistics().plan_reason;
  EXPECT_FALSE(q.options().sizing);
  const pdd::any_sizing f = q.meshing().sizing;
  ASSERT_TRUE(f);
  EXPECT_LT(f.area_at({0.50005, 5e-5}), 1e-7) << "F is small beside the notch";
}

} // namespace
} // namespace run_plan_test
