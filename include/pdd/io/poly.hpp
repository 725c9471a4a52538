/// \file poly.hpp
/// Triangle's .poly format: pdd::read_poly / pdd::parse_poly (strict reader) and
/// pdd::write_poly (bit-exact writer). Format: https://www.cs.cmu.edu/~quake/triangle.poly.html
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/errors.hpp>
#include <pdd/io/atomic_file.hpp>
#include <pdd/io/detail/poly.hpp>
#include <pdd/io/detail/text.hpp>

#include <cmath>
#include <filesystem>
#include <istream>
#include <ostream>
#include <string>

namespace pdd {

/// Parses a Triangle .poly file from a stream.
///
/// The format is read exactly as Triangle documents it: `#` starts a comment anywhere on a
/// line, blank lines are skipped, each record is one line.
///  - `<#vertices> <dimension=2> <#attributes> <#boundary markers 0|1>`, then the vertex
///    records `<id> <x> <y> [attributes] [marker]`. Ids start at 0 or 1 (the first record
///    decides, as in Triangle) and must be consecutive. Attributes are kept in
///    pslg::vertex_attributes (vertex_attribute_count per vertex); missing markers are 0. A vertex
///    count of 0 means the vertices are in the sibling .node file `<dir_for_node_file or the
///    directory of filename_for_messages>/<stem>.node`, read with the same rules (the rest of the
///    .node file is ignored, as in Triangle).
///  - `<#segments> <#boundary markers 0|1>`, then `<id> <endpoint> <endpoint> [marker]`.
///  - `<#holes>`, then `<id> <x> <y>`.
///  - optionally `<#regions>`, then `<id> <x> <y> <attribute> [<maximum area>]` (a missing
///    area is stored as -1: no constraint); nothing may follow this section.
/// Numbers are parsed with std::from_chars (locale-independent); a number must fill its whole
/// field. Segment/hole/region ids must be non-negative integers but are otherwise ignored, as
/// Triangle ignores them. The result is not validated geometrically (see pslg validation).
///
/// \param filename_for_messages the name used in error messages ("name:line: ...").
/// \throws pdd::input_error "file:line: expected ..." for every malformed input: wrong field
///   counts, non-numeric fields or trailing junk, NaN/infinite coordinates, counts that are
///   negative, >= 2^31 or larger than the rest of the file, a dimension other than 2, non-
///   consecutive vertex ids, negative or out-of-range segment endpoints, a truncated file (at
///   the line after the last one), a missing .node sibling (at the header line), content after
///   the regions section. Never returns a partial result.
/// \throws pdd::error when the stream or the .node sibling cannot be read.
/// Complexity: linear in the file size (the whole text is read into memory first).
/// Thread-safety: reentrant.
inline pslg parse_poly(std::istream& in, const std::string& filename_for_messages,
                       const std::filesystem::path& dir_for_node_file = {}) {
  const std::string text = detail::slurp(in, filename_for_messages);
  return detail::parse_poly_text(text, filename_for_messages, dir_for_node_file);
}

/// Reads a Triangle .poly file (see parse_poly for the accepted format and errors); a sibling
/// .node file is looked up in the same directory. Error messages name `path` as given.
/// \throws pdd::input_error for malformed content, pdd::error if the file cannot be opened.
inline pslg read_poly(const std::filesystem::path& path) {
  const std::string text = detail::slurp_file(path);
  return detail::parse_poly_text(text, path.string(), path.parent_path());
}

namespace detail {

/// Writes g in .poly form to `os` (1-based ids, the vertex attributes, one vertex and one
/// segment marker column, the regions section only when g has regions).
inline void write_poly_stream(std::ostream& os, const pslg& g) {
  text_sink out(os);
  out.put("# pdd .poly: vertices <#> <dim> <#attributes> <#markers>\n");
  const std::size_t na = g.vertex_attribute_count;
  out.integer(g.vertices.size()).put(" 2 ").integer(na).put(" 1\n");
  for (std::size_t i = 0; i < g.vertices.size(); ++i) {
    out.integer(i + 1).put(' ').num(g.vertices[i].x).put(' ').num(g.vertices[i].y).put(' ');
    for (std::size_t a = 0; a < na; ++a)
      out.num(g.vertex_attributes[i * na + a]).put(' ');
    out.integer(g.vertex_markers.empty() ? 0 : g.vertex_markers[i]).put('\n');
  }
  out.put("# segments <#> <#markers>\n").integer(g.segments.size()).put(" 1\n");
  for (std::size_t i = 0; i < g.segments.size(); ++i) {
    const segment& s = g.segments[i];
    out.integer(i + 1).put(' ').integer(std::size_t{s.a} + 1).put(' ');
    out.integer(std::size_t{s.b} + 1).put(' ').integer(s.marker).put('\n');
  }
  out.put("# holes\n").integer(g.holes.size()).put('\n');
  for (std::size_t i = 0; i < g.holes.size(); ++i)
    out.integer(i + 1).put(' ').num(g.holes[i].x).put(' ').num(g.holes[i].y).put('\n');
  if (!g.regions.empty()) {
    out.put("# regions <#>: <id> <x> <y> <attribute> <maximum area>\n");
    out.integer(g.regions.size()).put('\n');
    for (std::size_t i = 0; i < g.regions.size(); ++i) {
      const region& r = g.regions[i];
      out.integer(i + 1).put(' ').num(r.p.x).put(' ').num(r.p.y).put(' ').num(r.attribute);
      out.put(' ').num(r.max_area).put('\n');
    }
  }
  out.flush();
}

/// Checks that g can be written as a .poly that reads back equal.
inline void check_writable(const pslg& g, const std::filesystem::path& path) {
  const std::string where = "cannot write '" + path.string() + "': ";
  if (g.vertices.empty())
    throw error(where + "the PSLG has no vertices (a .poly with 0 vertices refers to a .node)");
  if (!g.vertex_markers.empty() && g.vertex_markers.size() != g.vertices.size())
    throw error(where + "vertex_markers and vertices differ in size");
  if (g.vertex_attributes.size() != g.vertices.size() * g.vertex_attribute_count)
    throw error(where + "vertex_attributes does not hold vertex_attribute_count values per vertex");
  for (const double a : g.vertex_attributes)
    if (!std::isfinite(a)) throw error(where + "a vertex attribute is NaN or infinite");
  const auto finite = [](point p) { return std::isfinite(p.x) && std::isfinite(p.y); };
  for (std::size_t i = 0; i < g.vertices.size(); ++i)
    if (!finite(g.vertices[i]))
      throw error(where + "vertex " + std::to_string(i) + " has a NaN or infinite coordinate");
  for (std::size_t i = 0; i < g.segments.size(); ++i)
    if (g.segments[i].a >= g.vertices.size() || g.segments[i].b >= g.vertices.size())
      throw error(where + "segment " + std::to_string(i) + " refers to a missing vertex");
  for (std::size_t i = 0; i < g.holes.size(); ++i)
    if (!finite(g.holes[i]))
      throw error(where + "hole " + std::to_string(i) + " has a NaN or infinite coordinate");
  for (std::size_t i = 0; i < g.regions.size(); ++i) {
    const region& r = g.regions[i];
    if (!finite(r.p) || !std::isfinite(r.attribute) || !std::isfinite(r.max_area))
      throw error(where + "region " + std::to_string(i) + " has a NaN or infinite value");
  }
}

} // namespace detail

/// Writes a PSLG as a Triangle .poly file, atomically. Coordinates, vertex attributes,
/// regional attributes and areas are written in the shortest form that reads back to the same bits
/// (std::to_chars), so read_poly(write_poly(g)) == g bit for bit (vertex_markers are written as 0
/// when empty). Ids are 1-based, as Triangle writes them. \throws pdd::error naming the path when g
/// has no vertices, mismatched marker sizes, a
///   segment endpoint out of range or a non-finite number, or when writing fails (nothing is
///   left behind then; see write_file_atomically).
/// Complexity: linear. Thread-safety: reentrant.
inline void write_poly(const std::filesystem::path& path, const pslg& g) {
  detail::check_writable(g, path);
  write_file_atomically(path, [&](std::ostream& os) { detail::write_poly_stream(os, g); });
}

} // namespace pdd
