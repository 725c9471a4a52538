/// \file poly_writer.hpp
/// Implementation of pdd::write_poly: the .poly text of a pslg and the checks that it can be
/// written (ids in range, finite coordinates).
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/errors.hpp>
#include <pdd/io/detail/text.hpp>

#include <cmath>
#include <filesystem>
#include <ostream>
#include <string>

namespace pdd::detail {

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

} // namespace pdd::detail
