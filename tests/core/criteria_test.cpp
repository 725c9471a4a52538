// Tests of the core value types and the error hierarchy.
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/errors.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace criteria_test {
TEST(Criteria, DefaultIsRatioSqrt2) {
  const pdd::mesh_criteria c;
  EXPECT_NEAR(c.ratio_bound(), std::numbers::sqrt2, 1e-12);
  EXPECT_NEAR(c.shape_bound(), 0.125, 1e-12);
  EXPECT_GT(c.min_angle_deg, 20.7);
  EXPECT_LT(c.min_angle_deg, 20.71);
  EXPECT_TRUE(std::isinf(c.max_area));
}

TEST(Criteria, AngleRatioRoundTrip) {
  for (double deg : {5.0, 20.0, 25.0, 30.0, 33.0})
    EXPECT_NEAR(pdd::min_angle_for_ratio(pdd::ratio_for_min_angle(deg)), deg, 1e-10);
}

TEST(Errors, InputErrorCarriesFileAndLine) {
  const pdd::input_error e("a.poly", 12, "expected 3 numbers");
  EXPECT_STREQ(e.what(), "a.poly:12: expected 3 numbers");
  EXPECT_EQ(e.line(), 12u);
  EXPECT_EQ(e.file(), "a.poly");
}

TEST(Errors, AssertThrowsInternalError) {
  EXPECT_THROW(PDD_ASSERT(1 + 1 == 3), pdd::internal_error);
  EXPECT_NO_THROW(PDD_ASSERT(1 + 1 == 2));
}

} // namespace criteria_test
