// CI-sized (ctest label "ci": the release preset runs it, the sanitizer presets do not build
// it) version of tests/long/gradation_long_test.cpp: Algorithm 7.1 on Table 7.1's d^2 field of
// the pipe (global gradation 1/841): Conditions 1 and 2 hold on every subdomain and separator
// (recomputed from pdd::sizing_range) over more than a thousand subdomains. The long test adds
// d^4 (1/707281).
#include <pdd/geometry/model_domains.hpp>
#include <pdd/madd/gradation_control.hpp>
#include <pdd/madd/validate_decomposition.hpp>
#include <pdd/sizing/expression.hpp>

#include <gradation_checks.hpp>
#include <table71_fields.hpp>

#include <gtest/gtest.h>

namespace gradation_ci_test {

TEST(CiSizedGradationControl, ReachesR1AndR2OnTable71SquareField) {
  const pdd::pslg g = pdd::pipe_domain();
  const pdd::any_sizing f = pdd::expression_sizing(pdd::test::pipe_distance_field(2, 1e-9));
  const pdd::gradation_options o{.min_subdomain_triangles = 0};
  pdd::gradation_report rep;
  const pdd::decomposition d = pdd::gradation_controlled_decompose(g, f, o, {}, {}, &rep);
  EXPECT_TRUE(pdd::validate_decomposition(d, g).ok());
  pdd::test::expect_gradation_conditions(d, f, o, rep);
  EXPECT_GT(d.subdomains.size(), 1000u);
}

} // namespace gradation_ci_test
