// Tests of the drivers' shared error report (examples/drivers/exit_code.hpp): the exit code of
// every pdd error type, and the messages run_reporting_errors prints.
#include "../../examples/drivers/exit_code.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <utility>

namespace exit_code_test {
namespace {

using pdd::drivers::exit_code_for;

TEST(ExitCode, EveryErrorType) {
  EXPECT_EQ(exit_code_for(pdd::input_error("a.poly", 3, "bad")), pdd::drivers::bad_input);
  EXPECT_EQ(exit_code_for(pdd::geometry_error("crossing", {1, 2})), pdd::drivers::bad_input);
  EXPECT_EQ(exit_code_for(pdd::decomposition_error("thin")), pdd::drivers::bad_input);
  EXPECT_EQ(exit_code_for(pdd::decoupling_error("k")), pdd::drivers::bad_input);
  EXPECT_EQ(exit_code_for(pdd::limit_error("memory")), pdd::drivers::bad_input);
  EXPECT_EQ(exit_code_for(pdd::error("cannot write")), pdd::drivers::bad_input);
  EXPECT_EQ(exit_code_for(pdd::meshing_error(3, "kernel")), pdd::drivers::internal);
  EXPECT_EQ(exit_code_for(pdd::internal_error("invariant")), pdd::drivers::internal);
  EXPECT_EQ(exit_code_for(pdd::unresolvable_input_error(3, "sub-degree")),
            pdd::drivers::unresolvable);
}

// A subdomain wrapper keeps an unresolvable_input_error's class and names the subdomain; any
// other meshing_error stays one.
TEST(ExitCode, RethrowForSubdomainKeepsTheClass) {
  const auto wrapped = [](const auto& thrown) -> std::pair<int, std::string> {
    try {
      try {
        throw thrown; // by its own class
      } catch (const pdd::meshing_error& e) {
        pdd::rethrow_for_subdomain(e, 7);
      }
    } catch (const pdd::meshing_error& e) {
      return {exit_code_for(e), e.what()};
    }
    return {};
  };
  EXPECT_EQ(wrapped(pdd::unresolvable_input_error(-1, "angle")),
            std::make_pair(5, std::string("subdomain 7: angle")));
  EXPECT_EQ(wrapped(pdd::meshing_error(-1, "kernel")),
            std::make_pair(4, std::string("subdomain 7: kernel")));
}

TEST(ExitCode, ReportsAndReturns) {
  const auto run = [](auto body) {
    testing::internal::CaptureStderr();
    const int rc = pdd::drivers::run_reporting_errors("pdd-x", "in.poly", body);
    return std::make_pair(rc, testing::internal::GetCapturedStderr());
  };
  EXPECT_EQ(run([] { return 3; }), std::make_pair(3, std::string()));
  EXPECT_EQ(run([]() -> int {
              throw pdd::geometry_error("segments 1 and 2 cross", {1, 2});
            }),
            std::make_pair(1, std::string("pdd-x: error: in.poly: segments 1 and 2 cross\n")));
  EXPECT_EQ(run([]() -> int { throw pdd::decomposition_error("too thin"); }),
            std::make_pair(1, std::string("pdd-x: error: in.poly: cannot decompose: too thin\n")));
  EXPECT_EQ(run([]() -> int { throw pdd::input_error("a.poly", 3, "bad"); }),
            std::make_pair(1, std::string("pdd-x: error: a.poly:3: bad\n")));
  EXPECT_EQ(run([]() -> int { throw pdd::meshing_error(5, "failed"); }),
            std::make_pair(4, std::string("pdd-x: internal error: subdomain 5: failed\n")));
  EXPECT_EQ(run([]() -> int { throw pdd::unresolvable_input_error(2, "angle"); }),
            std::make_pair(5, std::string("pdd-x: error: subdomain 2: angle\n")));
  EXPECT_EQ(run([]() -> int { throw std::logic_error("oops"); }),
            std::make_pair(4, std::string("pdd-x: internal error: oops\n")));
}

} // namespace

} // namespace exit_code_test
