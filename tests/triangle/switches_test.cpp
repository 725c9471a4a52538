// Triangle's switch strings: what parse_switches accepts, what it refuses and why.
#include <pdd/triangle/switches.hpp>

#include <gtest/gtest.h>

#include <string>

namespace switches_test {
using pdd::triangle::parse_switches;
using pdd::triangle::switch_error;

namespace {
std::string refusal(const std::string& s) {
  try {
    parse_switches(s);
  } catch (const switch_error& e) {
    return e.what();
  }
  return "accepted";
}
} // namespace

TEST(Switches, QualityAndArea) {
  const auto s = parse_switches("pq30a0.01");
  EXPECT_TRUE(s.poly);
  EXPECT_TRUE(s.quality);
  EXPECT_EQ(s.min_angle_deg, 30.0);
  EXPECT_EQ(s.max_area, 0.01);
  EXPECT_FALSE(s.regional_areas);
  EXPECT_EQ(pdd::triangle::to_string(s), "pq30a0.01");
}

TEST(Switches, BareQIsTwentyDegreesAndNoQIsZero) {
  EXPECT_EQ(parse_switches("pq").min_angle_deg, 20.0);
  EXPECT_EQ(parse_switches("q.5").min_angle_deg, 0.5);
  const auto a = parse_switches("pa1");
  EXPECT_TRUE(a.quality); // Triangle: a implies quality refinement, angle 0
  EXPECT_EQ(a.min_angle_deg, 0.0);
}

TEST(Switches, NumbersStopAtTheFirstOtherCharacter) {
  // Triangle reads only digits and '.': a2.6e-7 would be a = 2.6, then e, - and 7 (refused as
  // an exponent).
  EXPECT_EQ(parse_switches("a0.00000026").max_area, 0.00000026);
  EXPECT_NE(refusal("a2.6e-7").find("switch -a2.6e-"), std::string::npos);
  const auto s = parse_switches("q25.5Aa");
  EXPECT_EQ(s.min_angle_deg, 25.5);
  EXPECT_TRUE(s.regional_attributes);
  EXPECT_TRUE(s.regional_areas);
  EXPECT_LT(s.max_area, 0.0);
}

TEST(Switches, AreaWithAndWithoutNumber) {
  const auto s = parse_switches("-pa0.5a");
  EXPECT_EQ(s.max_area, 0.5);
  EXPECT_TRUE(s.regional_areas);
  EXPECT_EQ(pdd::triangle::to_string(s), "pa0.5a");
}

TEST(Switches, EveryFlag) {
  const auto s = parse_switches("pAQVVNEPBOzjncev");
  EXPECT_TRUE(s.convex && s.edges && s.voronoi);
  EXPECT_EQ(pdd::triangle::to_string(s), "pcAQVVNEPBOzjnev");
  EXPECT_TRUE(s.poly && s.regional_attributes && s.quiet);
  EXPECT_EQ(s.verbose, 2u);
  EXPECT_TRUE(s.no_node && s.no_ele && s.no_poly && s.no_boundary_markers);
  EXPECT_TRUE(s.ignore_holes && s.zero_based && s.jettison && s.neighbors);
  EXPECT_FALSE(s.quality);
  EXPECT_TRUE(parse_switches("pI").no_iteration_numbers);
  EXPECT_EQ(pdd::triangle::to_string(parse_switches("")), "");
}

TEST(Switches, RefusesUnsupportedSwitchesByName) {
  for (const char c : std::string("uwWYgohH?x7%")) {
    const std::string msg = refusal(std::string("p") + c);
    EXPECT_NE(msg.find(std::string("switch -") + c), std::string::npos) << msg;
  }
  EXPECT_TRUE(parse_switches("rpq").refine);
  EXPECT_NE(refusal("pg").find("OFF"), std::string::npos);
  EXPECT_NE(refusal("pY").find("boundary"), std::string::npos);
  EXPECT_NE(refusal("pqYY").find("need segment splits"), std::string::npos);
  EXPECT_NE(refusal("pk").find("supported: p r q a A c D S e v o2 C Q V N E P B I O z j n, and i "
                               "F l s L X, which pdd ignores"),
            std::string::npos);
  EXPECT_TRUE(parse_switches("pqC").check) << "C runs pdd's verifier";
  EXPECT_EQ(pdd::triangle::to_string(parse_switches("Cpq")), "pq20C");
}

TEST(Switches, ConformingDelaunayAndSteinerBudget) {
  const auto d = parse_switches("pDq");
  EXPECT_TRUE(d.conforming && d.quality);
  EXPECT_LT(d.max_steiner, 0) << "no budget without S";
  EXPECT_EQ(pdd::triangle::to_string(d), "pq20D");
  EXPECT_EQ(parse_switches("pqS25").max_steiner, 25);
  EXPECT_EQ(parse_switches("pS").max_steiner, 0) << "Triangle reads a bare S as 0";
  const auto s = parse_switches("pS0q30");
  EXPECT_EQ(s.max_steiner, 0);
  EXPECT_EQ(s.min_angle_deg, 30.0);
  EXPECT_EQ(pdd::triangle::to_string(parse_switches("pqS7D")), "pq20DS7");
  EXPECT_NE(refusal("pS99999999999999999999").find("too large"), std::string::npos);
}

TEST(Switches, SecondOrderIsO2Only) {
  const auto s = parse_switches("pqo2e");
  EXPECT_TRUE(s.second_order && s.edges && s.quality);
  EXPECT_EQ(pdd::triangle::to_string(s), "pq20eo2");
  EXPECT_NE(refusal("po3").find("switch -o3"), std::string::npos);
  EXPECT_NE(refusal("po").find("only higher order is -o2"), std::string::npos);
  EXPECT_NE(refusal("poq").find("switch -oq"), std::string::npos);
}

TEST(Switches, TrianglesInternalChoicesAreAcceptedAndIgnored) {
  const auto s = parse_switches("pqiFlsLX");
  EXPECT_EQ(s.ignored, "iFlsLX");
  EXPECT_TRUE(s.quality);
  EXPECT_EQ(pdd::triangle::to_string(s), "pq20iFlsLX");
  EXPECT_EQ(parse_switches("pq").ignored, "");
}

TEST(Switches, RefusesBadNumbers) {
  EXPECT_NE(refusal("a0").find("greater than zero"), std::string::npos);
  EXPECT_NE(refusal("a.").find("'.' is not a number"), std::string::npos);
  EXPECT_NE(refusal("q1.2.3").find("switch -q1.2.3"), std::string::npos);
  // an exponent is refused (Triangle would read a2.6, then e, - and 7), e after a number is not
  EXPECT_NE(refusal("pa2.6e-7").find("no exponent"), std::string::npos);
  EXPECT_NE(refusal("pq30E5").find("switch -q30E5"), std::string::npos);
  EXPECT_TRUE(parse_switches("pa0.5e").edges);
  EXPECT_TRUE(parse_switches("pq30ev").voronoi);
  EXPECT_NE(refusal("--p").find("switch --"), std::string::npos);
  // switches accumulate over several arguments, as Triangle reads them
  const auto s = parse_switches("-a0.5", parse_switches("-pq30"));
  EXPECT_TRUE(s.poly);
  EXPECT_EQ(s.min_angle_deg, 30.0);
  EXPECT_EQ(s.max_area, 0.5);
}

} // namespace switches_test
