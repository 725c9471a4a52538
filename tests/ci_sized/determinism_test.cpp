// CI-sized (ctest label "ci": the release preset runs it, the sanitizer presets do not build
// it): pdd::generate's mesh is bitwise the same at 1, 2, 3, 8 and 16 threads (oversubscribed on
// CI's two cores, so the tasks interleave in ways two threads never show) on every path: the
// uniform method (one k), the graded path under the uniform bound (Theorem 22) and under a
// sizing field, the geometric path (Algorithm 8.3's
// loop, for a tiny notch) and a general PSLG decoupled from its faces. N is given: the
// automatic N grows with the thread count (at least 4 subdomains per thread,
// pdd::automatic_subdomains), so only a given N promises the same mesh for every T.
#include <pdd/generate.hpp>
#include <pdd/geometry/model_domains.hpp>
#include <pdd/geometry/properties.hpp>
#include <pdd/sizing/expression.hpp>

#include "general_domains.hpp"
#include "mesh_compare.hpp"
#include "table71_fields.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <vector>

namespace determinism_test {
namespace {

struct path_case {
  std::string name;
  pdd::pslg domain;
  pdd::generate_options options;
  std::string path; // the path the plan must take
};

pdd::generate_options with_area(double max_area, std::size_t subdomains) {
  pdd::generate_options o;
  o.criteria.max_area = max_area;
  o.subdomains = subdomains;
  return o;
}

/// The unit square with a notch 1e-4 wide and deep (tests/pipeline/geometric_pipeline_test).
pdd::pslg notched_square() {
  pdd::pslg g;
  g.add_loop(
      std::vector<pdd::point>{
          {0, 0}, {0.5, 0}, {0.5, 1e-4}, {0.5001, 1e-4}, {0.5001, 0}, {1, 0}, {1, 1}, {0, 1}},
      0);
  return g;
}

std::vector<path_case> path_cases() {
  std::vector<path_case> out;
  const pdd::pslg key = pdd::key_domain();
  const pdd::generate_options bound = with_area(pdd::domain_area(key) / 26000.0, 16);
  out.push_back({"graded under the uniform bound", key, bound, "graded"}); // Theorem 22's k_i
  pdd::generate_options uniform = bound;
  uniform.decoupling.k_scale = 0.9; // one k for every subdomain: the uniform method
  out.push_back({"uniform", key, uniform, "uniform"});
  pdd::generate_options graded = with_area(1.0, 8);
  graded.sizing = pdd::expression_sizing(pdd::test::pipe_distance_field(1, 2e-4));
  out.push_back({"graded under a field", pdd::pipe_domain(), graded, "graded"});
  pdd::generate_options geometric = with_area(5e-6, 16);
  geometric.geometric_sizing = pdd::geometric_sizing_mode::on;
  out.push_back({"geometric", notched_square(), geometric, "geometric"});
  pdd::pslg grid = pdd::test::t_junction_grid();
  grid.rule = pdd::domain_rule::triangle;
  out.push_back({"general", grid, with_area(0.005, 4), "graded"});
  return out;
}

} // namespace

TEST(Determinism, EveryPathBitwiseAtOneTwoThreeEightSixteenThreads) {
  for (path_case& c : path_cases()) {
    SCOPED_TRACE(c.name);
    c.options.threads = 1;
    const pdd::generate_result one = pdd::generate(c.domain, c.options);
    EXPECT_EQ(one.statistics.path, c.path) << one.statistics.plan_reason;
    EXPECT_GT(one.statistics.subdomains, 1u);
    std::printf("%s: path %s, %zu subdomains, %zu triangles\n", c.name.c_str(),
                one.statistics.path.c_str(), one.statistics.subdomains, one.mesh.triangles.size());
    for (const unsigned threads : {2u, 3u, 8u, 16u}) {
      c.options.threads = threads;
      EXPECT_TRUE(pdd::test::bitwise_equal(one.mesh, pdd::generate(c.domain, c.options).mesh))
          << "1 vs " << threads << " threads";
    }
  }
}

} // namespace determinism_test
