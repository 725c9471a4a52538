/// \file switches.hpp
/// (Included by pdd/triangle/switches.hpp after its types.) Implementation of
/// pdd::triangle::parse_switches: the numbers after q and a, the flag letters, and the reasons
/// given for the switches pdd refuses.
#pragma once

#include <pdd/errors.hpp>

#include <charconv>
#include <cmath>
#include <string>
#include <string_view>
#include <system_error>

namespace pdd::triangle::detail {

/// The digits and '.' from position i on (Triangle's rule); advances i past them.
inline std::string_view number_after(std::string_view text, std::size_t& i) {
  const std::size_t start = i;
  while (i < text.size() && ((text[i] >= '0' && text[i] <= '9') || text[i] == '.'))
    ++i;
  return text.substr(start, i - start);
}

/// A group of switch letters pdd refuses, and why (the text after "switch -<letter>").
struct refused_switches {
  std::string_view letters;
  std::string_view reason;
};

inline constexpr refused_switches refusal_reasons[] = {
    {"u", " (a user-defined triunsuitable test) is not supported"},
    {"wW", " (weighted Delaunay) is not supported"},
    {"Y", " (-Y: no Steiner points on the boundary, -YY: on any segment) is not supported: "
          "pdd's guarantees need segment splits (Delaunay refinement splits a segment that a "
          "new vertex would encroach instead of inserting that vertex, which is how q's angle "
          "bound and D's Delaunay property are met next to segments; without splits neither "
          "holds, nor does refinement end)"},
    {"g", " (OFF output for Geomview) is not supported"},
    {"hH?", " (help) is not a meshing switch; run pdd-triangle --help"},
};

/// Why a switch letter is refused (the message names the switch).
inline std::string refusal(char c) {
  const std::string sw = std::string("switch -") + c;
  for (const refused_switches& r : refusal_reasons)
    if (r.letters.find(c) != std::string_view::npos) return sw + std::string(r.reason);
  return sw + " is not a Triangle switch pdd supports (supported: p r q a A c D S e v o2 C Q V N "
              "E P B I O z j n, and i F l s L X, which pdd ignores)";
}

/// The count after `S` at position i (digits only; none: 0, as Triangle reads a bare S);
/// advances i past it. \throws switch_error for a count too large for a long long.
inline long long read_steiner_count(std::string_view text, std::size_t& i) {
  const std::size_t start = i;
  while (i < text.size() && text[i] >= '0' && text[i] <= '9')
    ++i;
  long long n = 0;
  const auto r = std::from_chars(text.data() + start, text.data() + i, n);
  if (i > start && r.ec != std::errc{})
    throw switch_error("switch -S" + std::string(text.substr(start, i - start)) +
                       ": the Steiner point count is too large");
  return n;
}

/// The order after `o` at position i (Triangle's -o2; no other order exists): advances i past
/// it. \throws switch_error for a missing or other order.
inline void read_order(std::string_view text, std::size_t& i) {
  if (i < text.size() && text[i] == '2') {
    ++i;
    return;
  }
  throw switch_error("switch -o" + std::string(text.substr(i, 1)) +
                     ": Triangle's only higher order is -o2 (six-node triangles)");
}

/// Triangle's switches that choose its internal algorithms (pdd accepts and ignores them).
inline constexpr std::string_view internal_switches = "iFlsLX";

/// A number after q or a, read with std::from_chars (digits and '.' only, the characters
/// Triangle reads there). \throws switch_error for `1.2.3` and the like.
inline double switch_number(std::string_view number, const char* letter) {
  double v = 0.0;
  const auto r = std::from_chars(number.data(), number.data() + number.size(), v);
  if (r.ec != std::errc{} || r.ptr != number.data() + number.size() || !std::isfinite(v))
    throw switch_error(std::string("switch -") + letter + std::string(number) + ": '" +
                       std::string(number) + "' is not a number");
  return v;
}

/// Refuses an exponent after the number of q or a (`a2.6e-7`): Triangle would read `a2.6`,
/// then the switches e, - and 7, which is never what was meant. `i` is just past the number.
inline void refuse_exponent(std::string_view text, std::size_t i, char letter,
                            std::string_view number) {
  if (number.empty() || i + 1 >= text.size() || (text[i] != 'e' && text[i] != 'E')) return;
  const char next = text[i + 1];
  if ((next >= '0' && next <= '9') || next == '-' || next == '+')
    throw switch_error(std::string("switch -") + letter + std::string(number) + text[i] + next +
                       "...: Triangle reads only digits and '.' after -" + letter +
                       " (no exponent); write the number out, e.g. -a0.00000026");
}

/// A switch letter without a number and the flag of switches it sets.
struct flag_switch {
  char letter;
  bool switches::*flag;
};

inline constexpr flag_switch flag_switches[] = {
    {'p', &switches::poly},
    {'r', &switches::refine},
    {'c', &switches::convex},
    {'D', &switches::conforming},
    {'e', &switches::edges},
    {'v', &switches::voronoi},
    {'A', &switches::regional_attributes},
    {'Q', &switches::quiet},
    {'N', &switches::no_node},
    {'E', &switches::no_ele},
    {'P', &switches::no_poly},
    {'B', &switches::no_boundary_markers},
    {'I', &switches::no_iteration_numbers},
    {'O', &switches::ignore_holes},
    {'z', &switches::zero_based},
    {'j', &switches::jettison},
    {'n', &switches::neighbors},
    {'C', &switches::check},
};

/// Sets the flag of a letter without a number (V counts; i F l s L X are kept in
/// switches::ignored); false for letters pdd does not support.
inline bool set_flag(switches& s, char c) {
  if (c == 'V') {
    ++s.verbose;
    return true;
  }
  if (internal_switches.find(c) != std::string_view::npos) {
    s.ignored += c;
    return true;
  }
  for (const flag_switch& f : flag_switches)
    if (f.letter == c) {
      s.*f.flag = true;
      return true;
    }
  return false;
}

/// Shortest decimal form of v without an exponent (what Triangle can read back).
inline std::string plain_number(double v) {
  char buf[400];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed);
  return std::string(buf, r.ptr);
}

/// The switches as one canonical string (see pdd::triangle::to_string).
inline std::string format_switches(const switches& s) {
  std::string out;
  const auto flag = [&out](bool on, char c) {
    if (on) out += c;
  };
  flag(s.poly, 'p');
  flag(s.refine, 'r');
  flag(s.convex, 'c');
  if (s.quality && s.min_angle_deg > 0.0) out += 'q' + plain_number(s.min_angle_deg);
  if (s.max_area > 0.0) out += 'a' + plain_number(s.max_area);
  flag(s.regional_areas, 'a');
  flag(s.conforming, 'D');
  if (s.max_steiner >= 0) out += 'S' + std::to_string(s.max_steiner);
  flag(s.regional_attributes, 'A');
  flag(s.quiet, 'Q');
  out.append(s.verbose, 'V');
  flag(s.no_node, 'N');
  flag(s.no_ele, 'E');
  flag(s.no_poly, 'P');
  flag(s.no_boundary_markers, 'B');
  flag(s.no_iteration_numbers, 'I');
  flag(s.ignore_holes, 'O');
  flag(s.zero_based, 'z');
  flag(s.jettison, 'j');
  flag(s.neighbors, 'n');
  flag(s.edges, 'e');
  flag(s.voronoi, 'v');
  if (s.second_order) out += "o2";
  flag(s.check, 'C');
  return out + s.ignored;
}

} // namespace pdd::triangle::detail
