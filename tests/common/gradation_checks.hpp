// Checks of Algorithm 7.1's Conditions 1-2 on a decomposition, recomputed independently of
// pdd::gradation_report (shared by tests/madd and tests/long).
#pragma once

#include <pdd/madd/gradation_control.hpp>
#include <pdd/madd/subdomain_region.hpp>
#include <pdd/sizing/sizing_range.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace pdd::test {

/// Asserts Conditions 1 and 2 on every subdomain and interface from pdd::sizing_range over
/// each subdomain's region with Algorithm 7.1's grid rule (o.range; independently of the
/// report), and that the report agrees.
inline void expect_gradation_conditions(const pdd::decomposition& d, const pdd::any_sizing& f,
                                        const pdd::gradation_options& o,
                                        const pdd::gradation_report& rep) {
  ASSERT_EQ(rep.bounds.size(), d.subdomains.size());
  std::vector<double> lo;
  for (std::size_t s = 0; s < d.subdomains.size(); ++s) {
    const pdd::sizing_bounds b = pdd::sizing_range(
        f, pdd::subdomain_region(d, static_cast<pdd::index_t>(s)).view(), o.range);
    EXPECT_LE(b.hi, o.r1 * b.lo) << "Condition 1, subdomain " << s;
    EXPECT_EQ(b.lo, rep.bounds[s].lo);
    lo.push_back(b.lo);
  }
  ASSERT_FALSE(d.interfaces.empty());
  for (const auto& c : d.interfaces) {
    EXPECT_LE(lo[c.a], o.r2 * lo[c.b]) << "Condition 2, " << c.a << " / " << c.b;
    EXPECT_LE(lo[c.b], o.r2 * lo[c.a]) << "Condition 2, " << c.b << " / " << c.a;
  }
  EXPECT_LE(rep.r1_max, o.r1);
  EXPECT_LE(rep.r2_max, o.r2);
  EXPECT_EQ(rep.condition_1_unmet + rep.condition_2_unmet + rep.condition_3_unmet, 0u);
  EXPECT_FALSE(rep.capped);
}

} // namespace pdd::test
