/// \file decomposition_report.hpp
/// pdd::decomposition_check_options and pdd::decomposition_report: what
/// pdd::validate_decomposition checks against and what it found.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace pdd {

/// What validate_decomposition checks against.
struct decomposition_check_options {
  double min_angle_deg = 60.0;       ///< Phi0
  double angle_tolerance_deg = 1e-9; ///< angles >= Phi0 - tolerance pass
  double area_tolerance = 1e-9;      ///< relative, for the sum of the areas
  std::size_t max_problems = 50;     ///< stop listing after this many
};

/// The findings of validate_decomposition.
struct decomposition_report {
  /// One message per violation found, at most decomposition_check_options::max_problems;
  /// empty: the decomposition passed.
  std::vector<std::string> problems;
  /// pdd::domain_area of the input PSLG.
  double domain_area = 0.0;
  /// The subdomains' areas added up (must match domain_area within area_tolerance).
  double area_sum = 0.0;
  /// Smallest angle (degrees) a separator forms with the boundary or another separator; 180
  /// when there is no separator.
  double min_separator_angle_deg = 180.0;
  /// True when no problem was found.
  bool ok() const noexcept { return problems.empty(); }
  /// The problems, one per line ("ok" when there are none).
  std::string summary() const {
    if (problems.empty()) return "ok";
    std::string s;
    for (const auto& p : problems)
      s += p + "\n";
    return s;
  }
};

} // namespace pdd
