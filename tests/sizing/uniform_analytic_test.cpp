// Tests of the SizingField models uniform_sizing and analytic_sizing.
#include <pdd/concepts/sizing_field.hpp>
#include <pdd/sizing/analytic.hpp>
#include <pdd/sizing/uniform.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace uniform_analytic_test {
TEST(Sizing, UniformAndAnalytic) {
  const pdd::uniform_sizing u{0.5};
  EXPECT_EQ(u.area_at({3, 4}), 0.5);
  const pdd::analytic_sizing a{[](pdd::point p) { return 1.0 + p.x * p.x; }};
  EXPECT_EQ(a.area_at({2, 0}), 5.0);
  static_assert(pdd::SizingField<decltype(a)>);
}

} // namespace uniform_analytic_test
