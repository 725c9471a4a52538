/// \file exit_code.hpp
/// The drivers' exit codes and their one error report: every pdd-* program maps a pdd::error to
/// its exit code with pdd::drivers::exit_code_for and prints it with run_reporting_errors.
#pragma once

#include <pdd/errors.hpp>

#include <cstdio>
#include <exception>
#include <string>

namespace pdd::drivers {

/// Exit codes of the pdd-* programs (docs/reference/pdd-mesh.md, "Exit codes").
enum exit_code : int {
  ok = 0,
  bad_input = 1,
  usage = 2,
  verification_failed = 3,
  internal = 4,
  unresolvable = 5 ///< valid input beyond the kernel's double precision (a sub-degree angle)
};

/// The exit code for a pdd error: unresolvable for a valid input the kernel cannot resolve in
/// double precision (pdd::unresolvable_input_error: an input limit, not a bug); internal for a
/// broken invariant (pdd::internal_error) or any other kernel failure (pdd::meshing_error),
/// which are bugs and never bad input; bad_input for everything else (files, geometry,
/// decomposition, decoupling, limits). Complexity O(1).
inline exit_code exit_code_for(const pdd::error& e) noexcept {
  if (dynamic_cast<const unresolvable_input_error*>(&e)) return unresolvable;
  if (dynamic_cast<const internal_error*>(&e) || dynamic_cast<const meshing_error*>(&e))
    return internal;
  return bad_input;
}

/// The message for e: geometry and decomposition errors are prefixed with the input file
/// they are about (other errors name their file, or none applies).
inline std::string describe(const pdd::error& e, const std::string& input) {
  if (dynamic_cast<const geometry_error*>(&e)) return input + ": " + e.what();
  if (dynamic_cast<const decomposition_error*>(&e))
    return input + ": cannot decompose: " + e.what();
  return e.what();
}

/// Runs body() and returns its exit code; on an exception prints "program: error: ..." (or
/// "program: internal error: ...") to standard error and returns exit_code_for it (internal
/// for an exception that is not a pdd::error).
template <class Body>
int run_reporting_errors(const char* program, const std::string& input, Body&& body) {
  try {
    return body();
  } catch (const pdd::error& e) {
    const exit_code code = exit_code_for(e);
    std::fprintf(stderr, "%s: %s: %s\n", program, code == internal ? "internal error" : "error",
                 describe(e, input).c_str());
    return code;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: internal error: %s\n", program, e.what());
    return internal;
  }
}

} // namespace pdd::drivers
