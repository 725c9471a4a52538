/// \file errors.hpp
/// The pdd error hierarchy. Bad input always throws one of these; internal invariants use
/// PDD_ASSERT, which throws pdd::internal_error with the file and line of the failed check.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace pdd {

/// Base class of every exception pdd throws.
class error : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// Malformed input file: what() reads "file:line: what was expected".
class input_error : public error {
public:
  /// An error at 1-based line `line` of `file`; what() is "file:line: message".
  input_error(std::string file, std::size_t line, const std::string& message)
      : error(file + ":" + std::to_string(line) + ": " + message), file_(std::move(file)),
        line_(line) {}
  /// The path of the malformed file, as given to the reader.
  const std::string& file() const noexcept { return file_; }
  /// The 1-based line of the file where the input went wrong.
  std::size_t line() const noexcept { return line_; }

private:
  std::string file_;
  std::size_t line_;
};

/// Invalid geometry (a PSLG that violates the domain definition). ids() names the offending
/// vertices, segments, holes or loops as the message says.
class geometry_error : public error {
public:
  /// An error with what() = `message`, naming the offending items `ids` (empty: none named).
  explicit geometry_error(const std::string& message, std::vector<std::size_t> ids = {})
      : error(message), ids_(std::move(ids)) {}
  /// The indices of the offending vertices, segments, holes or loops (which kind: the
  /// message says); empty when the error names none.
  const std::vector<std::size_t>& ids() const noexcept { return ids_; }

private:
  std::vector<std::size_t> ids_;
};

/// A PSLG that encloses no domain: its vertices are all collinear, or no face is enclosed by
/// segments, or hole points eat every enclosed face. Triangle writes an empty mesh for such an
/// input (pdd::triangle::triangulate does too, with triangulation::empty_domain saying why);
/// pdd::generate refuses it.
class empty_domain_error : public geometry_error {
public:
  using geometry_error::geometry_error;
};

/// The domain cannot be decomposed as asked (too thin, too few junction triangles, ...).
class decomposition_error : public error {
public:
  using error::error;
};

/// The decoupling path could not be built or was violated beyond repair.
class decoupling_error : public error {
public:
  using error::error;
};

/// The meshing kernel failed on a subdomain; subdomain() says which (-1: whole domain).
class meshing_error : public error {
public:
  /// A failure on subdomain `subdomain` (-1: the whole domain); what() is "subdomain s:
  /// message", or `message` alone for -1.
  meshing_error(long long subdomain, const std::string& message)
      : error(subdomain < 0 ? message : "subdomain " + std::to_string(subdomain) + ": " + message),
        subdomain_(subdomain) {}
  /// The subdomain the kernel failed on; -1 for the whole domain (no decomposition).
  long long subdomain() const noexcept { return subdomain_; }

private:
  long long subdomain_;
};

/// A valid input beyond what the kernel can resolve in double precision: two constraints at
/// an angle of a fraction of a degree (a split point rounds to beyond the neighbouring
/// constraint), or bounds asking for pieces of a segment below the floating-point resolution.
/// An input limit, not a bug: the drivers exit with their own code for it. A meshing_error
/// (subdomain() names where), so every handler of kernel failures still sees it; wrappers
/// that add the subdomain keep the type (pdd::rethrow_for_subdomain).
class unresolvable_input_error : public meshing_error {
public:
  /// As meshing_error(subdomain, message): `subdomain` -1 for the whole domain.
  using meshing_error::meshing_error;
};

/// Rethrows the meshing_error `e` for subdomain s, keeping its class (an
/// unresolvable_input_error stays one); as it is when it already names s.
/// \pre called while `e` is being handled (a catch block).
[[noreturn]] inline void rethrow_for_subdomain(const meshing_error& e, long long s) {
  if (e.subdomain() == s) throw;
  if (dynamic_cast<const unresolvable_input_error*>(&e) != nullptr)
    throw unresolvable_input_error(s, e.what());
  throw meshing_error(s, e.what());
}

/// A resource limit (memory estimate, refinement budget) would be exceeded.
class limit_error : public error {
public:
  using error::error;
};

/// An invalid sizing field: a non-positive or NaN area bound (with the point), an expression
/// that does not parse (column() > 0 names the 1-based column of the bad token), a field
/// whose minimum over a region cannot be bounded away from 0.
class sizing_error : public error {
public:
  /// An error with what() = `message`; `column` the 1-based column of a bad expression token,
  /// 0 (the default) when the error is not about an expression's text.
  explicit sizing_error(const std::string& message, std::size_t column = 0)
      : error(message), column_(column) {}
  /// The 1-based column of the expression token that does not parse; 0: not a parse error.
  std::size_t column() const noexcept { return column_; }

private:
  std::size_t column_;
};

/// A broken internal invariant: a bug in pdd, never bad input.
class internal_error : public error {
public:
  using error::error;
};

namespace detail {
[[noreturn]] inline void assertion_failed(const char* expr, const char* file, int line) {
  throw internal_error(std::string(file) + ":" + std::to_string(line) +
                       ": internal invariant failed: " + expr);
}
} // namespace detail

} // namespace pdd

/// Checks an internal invariant (always on; cheap checks only).
#define PDD_ASSERT(cond)                                                                           \
  do {                                                                                             \
    if (!(cond)) ::pdd::detail::assertion_failed(#cond, __FILE__, __LINE__);                       \
  } while (false)
