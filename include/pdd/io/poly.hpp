/// \file poly.hpp
/// Triangle's .poly format: pdd::read_poly / pdd::parse_poly (strict reader) and
/// pdd::write_poly (bit-exact writer). Format: https://www.cs.cmu.edu/~quake/triangle.poly.html
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/errors.hpp>
#include <pdd/io/atomic_file.hpp>
#include <pdd/io/detail/poly.hpp>
#include <pdd/io/detail/poly_writer.hpp>
#include <pdd/io/detail/text.hpp>

#include <cmath>
#include <filesystem>
#include <istream>
#include <ostream>
#include <string>
#include <utility>

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

/// Reads a Triangle .node file as a PSLG of vertices only (markers and attributes as read_poly
/// reads a vertex section; the rest of the file is ignored, as Triangle does): the input of
/// Triangle without -p, a vertex set.
/// \throws pdd::input_error "file:line: expected ..." for malformed content (a vertex count of
///   0 among them), pdd::error if the file cannot be opened.
/// Complexity: linear in the file size. Thread-safety: reentrant.
inline pslg read_node(const std::filesystem::path& path) {
  detail::vertex_section vs = detail::parse_node_text(detail::slurp_file(path), path.string());
  pslg g;
  g.vertices = std::move(vs.vertices);
  g.vertex_markers = std::move(vs.markers);
  g.vertex_attribute_count = vs.attribute_count;
  g.vertex_attributes = std::move(vs.attributes);
  return g;
}

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
