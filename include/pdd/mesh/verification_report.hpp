/// \file verification_report.hpp
/// The input and the output of pdd::verify (mesh/verify.hpp): verify_options and
/// verification_report.
#pragma once

#include <pdd/core/mesh_criteria.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace pdd {

/// Options of verify().
struct verify_options {
  /// Quality bound (min_angle_deg, checked with 1e-9 degrees slack), uniform area bound, and
  /// the encroachment rule the mesh was made under (which edges must be Delaunay).
  mesh_criteria criteria;
  /// Relative tolerance of |mesh area - domain area| / domain area.
  double area_tolerance = 1e-9;
  /// How many violations are described in messages (all are counted).
  std::size_t max_reported = 20;
  /// Per triangle: exempt from the quality (minimum angle) check only. Absent (the default):
  /// pdd's own rule, the one every mesh pdd makes is checked by (pdd::quality_exemptions: the
  /// shielded triangles of input angles < 60 deg on closed loops, dissertation 8.1; the
  /// cluster triangles at small angles between segments on other domains). Given: exactly
  /// these (an empty vector exempts none). All other checks apply to every triangle.
  std::optional<std::vector<char>> quality_exempt{};
  /// How the PSLG's faces are read. False (the default): as pdd::generate reads a user's PSLG
  /// (pdd::domain_as_generated: Triangle's rule unless it is one of closed loops), so that
  /// verify(generate(d).mesh, d) checks what generate meshed. True: by pslg::rule as given
  /// (e.g. pdd's own subdomains: odd nesting, no hole points).
  bool rule_as_given = false;
};

/// What verify() found. Counts are exact; messages describe the first max_reported
/// violations (ids and coordinates) in a fixed order: triangles by index, then duplicate
/// vertices, then segments by index, then isolated input vertices by index, then edges by their
/// endpoints, then the area.
struct verification_report {
  std::size_t delaunay_violations = 0;    ///< interior edges that are not locally Delaunay
  std::size_t orientation_violations = 0; ///< clockwise, degenerate or malformed triangles
  std::size_t missing_segments = 0;       ///< input segments that are no union of mesh edges
  std::size_t duplicate_vertices = 0;     ///< vertices at the coordinates of an earlier one
  /// Isolated input vertices (on no segment) inside the domain that no triangle uses.
  std::size_t missing_vertices = 0;
  std::size_t quality_violations = 0; ///< triangles with an angle below the bound
  std::size_t area_violations = 0;    ///< triangles larger than the area bound
  /// Edges in more than two triangles, interior edges used twice in the same direction, and
  /// boundary edges (in one triangle) that lie on no input segment.
  std::size_t nonmanifold_edges = 0;
  double area_domain = 0.0; ///< pdd::domain_area of the PSLG
  double area_mesh = 0.0;   ///< sum of the triangle areas
  bool area_ok = false;     ///< areas agree within the relative tolerance
  /// Descriptions of the first verify_options::max_reported violations, in the order above;
  /// empty when ok().
  std::vector<std::string> messages;

  /// True if no violation was found and the areas agree.
  bool ok() const noexcept {
    return delaunay_violations == 0 && orientation_violations == 0 && missing_segments == 0 &&
           duplicate_vertices == 0 && missing_vertices == 0 && quality_violations == 0 &&
           area_violations == 0 && nonmanifold_edges == 0 && area_ok;
  }
};

} // namespace pdd
