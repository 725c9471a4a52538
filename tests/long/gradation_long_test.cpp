// Long tests (ctest label "long"): Algorithm 7.1 on Table 7.1's steeper fields of the pipe,
// d^2 (gradation 1/841) and d^4 (1/707281): Conditions 1 and 2 hold on every subdomain and
// separator (recomputed from pdd::sizing_range), and the steeper field needs more subdomains.
#include <pdd/geometry/model_domains.hpp>
#include <pdd/madd/gradation_control.hpp>
#include <pdd/madd/validate_decomposition.hpp>
#include <pdd/sizing/expression.hpp>

#include <gradation_checks.hpp>
#include <table71_fields.hpp>

#include <gtest/gtest.h>

#include <string>

namespace gradation_long_test {
TEST(LongGradationControl, ReachesR1AndR2OnSteepTable71Fields) {
  const pdd::pslg g = pdd::pipe_domain();
  std::size_t previous = 0;
  for (const int p : {2, 4}) {
    SCOPED_TRACE("d^" + std::to_string(p));
    const pdd::any_sizing f = pdd::expression_sizing(pdd::test::pipe_distance_field(p, 1e-9));
    const pdd::gradation_options o{.min_subdomain_triangles = 0};
    pdd::gradation_report rep;
    const pdd::decomposition d = pdd::gradation_controlled_decompose(g, f, o, {}, {}, &rep);
    EXPECT_TRUE(pdd::validate_decomposition(d, g).ok());
    pdd::test::expect_gradation_conditions(d, f, o, rep);
    EXPECT_GT(d.subdomains.size(), previous + 1000);
    previous = d.subdomains.size();
    RecordProperty("subdomains_d" + std::to_string(p), static_cast<int>(previous));
  }
}

} // namespace gradation_long_test
