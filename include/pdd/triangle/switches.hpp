/// \file switches.hpp
/// pdd::triangle::switches and pdd::triangle::parse_switches: Triangle's command-line switch
/// string (`pq30a0.01`, Triangle 1.6's `triangle -h` text and its README), for pdd-triangle
/// and the Python `pdd.triangulate`. Switches pdd cannot honour are refused, never ignored.
#pragma once

#include <pdd/errors.hpp>

#include <string>
#include <string_view>

namespace pdd::triangle {

/// A switch string pdd does not accept: an unknown or unsupported switch (the message names
/// it and says why) or a malformed number.
class switch_error : public error {
public:
  using error::error;
};

/// The switches of one Triangle run that pdd supports (Triangle's letters in brackets).
struct switches {
  bool poly = false; ///< [p] mesh the PSLG of a .poly (set by a .poly file name too)
  /// [r] refine a previous mesh (.node and .ele; with p its .poly; with a bare a its .area)
  bool refine = false;
  /// [c] segments on the convex hull: with p, the hull of the PSLG's vertices is meshed; without
  /// p, the hull's edges are output as segments (a .poly file)
  bool convex = false;
  bool quality = false; ///< [q] or [a]: Delaunay refinement (Triangle: a implies quality)
  /// [D] conforming Delaunay: every triangle Delaunay (no vertex in its circumcircle), segments
  /// split as needed; the whole domain on one triangulation (detail/conforming.hpp)
  bool conforming = false;
  /// [S<n>] at most n Steiner points (vertices beyond the input; a bare S is 0, as in
  /// Triangle); negative: no limit. With q, a or D the whole domain on one triangulation.
  long long max_steiner = -1;
  /// [q<angle>] the minimum angle in degrees: 20 after a bare q, 0 without q (as Triangle).
  double min_angle_deg = 0.0;
  double max_area = -1.0;            ///< [a<area>] uniform area bound; negative: none
  bool regional_areas = false;       ///< [a] alone: the regions' area bounds apply
  bool regional_attributes = false;  ///< [A] a regional attribute per triangle
  bool quiet = false;                ///< [Q] no statistics
  unsigned verbose = 0;              ///< [V] quality statistics (repeatable)
  bool no_node = false;              ///< [N] no output .node (and no vertices in Python)
  bool no_ele = false;               ///< [E] no output .ele
  bool no_poly = false;              ///< [P] no output .poly
  bool no_boundary_markers = false;  ///< [B] no boundary markers in the output
  bool no_iteration_numbers = false; ///< [I] no .1 in output file names
  bool ignore_holes = false;         ///< [O] drop the hole points
  bool zero_based = false;           ///< [z] numbering from 0
  bool jettison = false;             ///< [j] drop vertices no triangle uses
  bool neighbors = false;            ///< [n] neighbours of every triangle (.neigh)
  bool edges = false;                ///< [e] every edge of the mesh (.edge)
  bool voronoi = false;              ///< [v] the Voronoi diagram (.v.node, .v.edge)
  /// [o2] six-node (subparametric quadratic) triangles: a node at the middle of every edge
  bool second_order = false;
  /// [C] check the mesh with pdd::verify (triangulation::check): Triangle checks its own data
  /// structures there; pdd checks what it made (exact Delaunay or constrained Delaunay,
  /// conformity, the domain's area, the angle and area bounds)
  bool check = false;
  /// [i F l s L X] accepted and ignored: they choose Triangle's internal algorithms
  /// (insertion, divide-and-conquer cuts, exact arithmetic), none of which change what pdd
  /// makes; the letters as given, for -V to report.
  std::string ignored;
};

} // namespace pdd::triangle

// The implementation works on the types above.
#include <pdd/triangle/detail/switches.hpp>

namespace pdd::triangle {

/// The switch letters parse_switches accepts, for messages and documentation.
inline constexpr std::string_view supported_switches =
    "p r q a A c D S e v o2 C Q V N E P B I O z j n i F l s L X";

/// Parses a switch string as Triangle does: one letter per switch, in any order and any
/// number of times; `S` takes the digits that follow it (none: 0, as Triangle reads a bare S);
/// `q` and `a` take the digits and '.' that follow them (so `a0.00000026`,
/// never `a2.6e-7`: Triangle reads no exponent, and neither does pdd: an `e` right after such a
/// number, followed by a digit or a sign, is refused as an exponent); a bare `a` asks for
/// the regional area bounds, and `a` with and without a number may both appear. A single
/// leading '-' is allowed. pdd-triangle parses each `-...` argument with it, passing the
/// switches so far as `s` (Triangle reads every argument that starts with '-').
/// `o` must be followed by `2` (o2: Triangle's only higher order).
/// \throws switch_error naming the switch for every letter that is not supported (see
///   detail::refusal for the reasons given), an area that is not > 0 or a number that does
///   not parse (`q1.2.3`), an exponent after a number (`a2.6e-7`), a Steiner count too large
///   for a long long or an order other than 2.
/// Complexity O(length). Thread-safety: reentrant.
inline switches parse_switches(std::string_view text, switches s = {}) {
  if (text.starts_with('-')) text.remove_prefix(1);
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i++];
    if (c == 'q' || c == 'a') {
      const std::string_view number = detail::number_after(text, i);
      detail::refuse_exponent(text, i, c, number);
      if (c == 'q') {
        s.quality = true;
        s.min_angle_deg = number.empty() ? 20.0 : detail::switch_number(number, "q");
      } else {
        s.quality = true;
        if (number.empty())
          s.regional_areas = true;
        else
          s.max_area = detail::switch_number(number, "a");
        if (!number.empty() && !(s.max_area > 0.0))
          throw switch_error("switch -a" + std::string(number) +
                             ": the maximum area must be greater than zero");
      }
      continue;
    }
    if (c == 'S') {
      s.max_steiner = detail::read_steiner_count(text, i);
      continue;
    }
    if (c == 'o') {
      detail::read_order(text, i);
      s.second_order = true;
      continue;
    }
    if (!detail::set_flag(s, c)) throw switch_error(detail::refusal(c));
  }
  return s;
}

/// Formats the switches back as one string (canonical order; numbers in shortest form).
inline std::string to_string(const switches& s) {
  return detail::format_switches(s);
}

} // namespace pdd::triangle
