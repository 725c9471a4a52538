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
  std::vector<std::string> problems;
  double domain_area = 0.0;
  double area_sum = 0.0;
  double min_separator_angle_deg = 180.0;
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
