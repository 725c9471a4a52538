// Tests of generate_options: the embedded madd_options is never silently overridden.
#include <pdd/errors.hpp>
#include <pdd/pipeline.hpp>

#include <gtest/gtest.h>

#include <limits>
#include <string>
#include <vector>

namespace options_test {
namespace {

std::string rejection(const pdd::generate_options& o) {
  try {
    pdd::check_generate_options(o);
  } catch (const pdd::decomposition_error& e) {
    return e.what();
  }
  return {};
}

TEST(GenerateOptions, DefaultsAndAgreeingValuesAreAccepted) {
  pdd::generate_options o;
  EXPECT_EQ(rejection(o), "");
  o.subdomains = 8;
  o.threads = 3;
  o.madd.subdomains = 8; // the same values: nothing is overridden
  o.madd.threads = 3;
  EXPECT_EQ(rejection(o), "");
}

TEST(GenerateOptions, ContradictionsAreRejectedByName) {
  pdd::generate_options o;
  o.subdomains = 8;
  o.madd.subdomains = 5;
  EXPECT_NE(rejection(o).find("madd.subdomains = 5 contradicts subdomains = 8"), std::string::npos);
  o.madd.subdomains = 8;
  o.madd.threads = 2;
  EXPECT_NE(rejection(o).find("madd.threads = 2 contradicts threads = 0"), std::string::npos);
  o.madd.threads = 0;
  o.madd.max_subdomain_area = 1.0;
  EXPECT_NE(rejection(o).find("madd.max_subdomain_area"), std::string::npos);
  // automatic N: a madd.subdomains other than the default cannot agree with it
  pdd::generate_options a;
  a.madd.subdomains = 16;
  EXPECT_NE(rejection(a).find("contradicts subdomains = 0"), std::string::npos);
}

TEST(GenerateOptions, ThePipelineChecksThem) {
  pdd::pslg g;
  g.add_loop(std::vector<pdd::point>{{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  pdd::generate_options o;
  o.subdomains = 4;
  o.madd.subdomains = 3;
  EXPECT_THROW(pdd::pipeline<>(g, o), pdd::decomposition_error);
  o.madd.subdomains = 4;
  EXPECT_NO_THROW(pdd::pipeline<>(g, o));
}

} // namespace

} // namespace options_test
