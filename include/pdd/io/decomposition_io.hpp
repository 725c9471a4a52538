/// \file decomposition_io.hpp
/// A text format for pdd::decomposition, so that a decomposition made once (pdd-decompose -o)
/// can be read back by a later step. Coordinates are written in the shortest form that reads
/// back bit for bit. The format, line by line (`#` starts a comment, blank lines are ignored):
///
///     pdd-decomposition 2
///     vertices <n>
///     <x> <y> <marker>                                   (n lines, vertex ids 0..n-1)
///     subdomains <m>
///     subdomain <area> <number of loops> <inner>         (m blocks, subdomain ids 0..m-1)
///     loop <number of edges>                             (first loop: outer, CCW; then holes, CW)
///     <vertex> e <segment id> <marker>                   (edge from <vertex> to the next one:
///     <vertex> i <interface id> <neighbour subdomain>     external, interface, or an interface
///     <vertex> s <interface id> <neighbour> <marker>      on an input segment,
///     edge_tag::on_segment) segment <a> <b> <segment id> <marker>              (<inner> lines
///     after the loops: the vertex <a>                                          subdomain's inner
///     constraints) interfaces <k> <a> <b> <number of vertices> <v0> <v1> ...         (k lines,
///     interface ids 0..k-1)
///
/// Version 1 (written before general PSLGs were decoupled: no `s` edges, no inner constraints,
/// `subdomain <area> <loops>`) is read as well.
#pragma once

#include <pdd/core/decomposition.hpp>
#include <pdd/errors.hpp>
#include <pdd/io/atomic_file.hpp>
#include <pdd/io/detail/decomposition_io.hpp>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace pdd {

/// Writes a decomposition in pdd's text format (atomically). \throws pdd::error on I/O failure.
inline void write_decomposition(const std::filesystem::path& path, const decomposition& d) {
  write_file_atomically(path, [&](std::ostream& os) {
    os << "# pdd decomposition: " << d.subdomains.size() << " subdomains\npdd-decomposition 2\n";
    os << "vertices " << d.vertices.size() << '\n';
    for (std::size_t i = 0; i < d.vertices.size(); ++i) {
      detail::put_double(os, d.vertices[i].x);
      os << ' ';
      detail::put_double(os, d.vertices[i].y);
      os << ' ' << (i < d.vertex_markers.size() ? d.vertex_markers[i] : 0) << '\n';
    }
    os << "subdomains " << d.subdomains.size() << '\n';
    for (const subdomain& s : d.subdomains) {
      os << "subdomain ";
      detail::put_double(os, s.area);
      os << ' ' << s.loops.size() << ' ' << s.inner.size() << '\n';
      for (std::size_t l = 0; l < s.loops.size(); ++l) {
        os << "loop " << s.loops[l].size() << '\n';
        for (std::size_t i = 0; i < s.loops[l].size(); ++i)
          detail::put_decomposition_edge(os, s.loops[l][i], s.tags[l][i]);
      }
      for (const inner_constraint& c : s.inner)
        if (c.segment == no_index)
          os << "vertex " << c.a << '\n';
        else
          os << "segment " << c.a << ' ' << c.b << ' ' << c.segment << ' ' << c.marker << '\n';
    }
    os << "interfaces " << d.interfaces.size() << '\n';
    for (const interface_curve& c : d.interfaces) {
      os << c.a << ' ' << c.b << ' ' << c.vertices.size();
      for (index_t v : c.vertices)
        os << ' ' << v;
      os << '\n';
    }
  });
}

/// Reads a decomposition written by write_decomposition.
/// \throws pdd::input_error "file:line: what was expected" for any malformed content (counts,
/// ids out of range, truncation), never a partial result.
inline decomposition read_decomposition(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw input_error(path.string(), 0, "cannot open the file");
  detail::decomposition_reader r(in, path.string());
  decomposition d;
  detail::read_decomposition_vertices(r, d);
  detail::read_decomposition_subdomains(r, d);
  detail::read_decomposition_interfaces(r, d);
  const std::size_t ni = d.interfaces.size();
  for (const subdomain& sd : d.subdomains)
    for (const auto& tags : sd.tags)
      for (const edge_tag& t : tags)
        if (t.type == edge_tag::kind::interface && t.id >= ni)
          throw input_error(path.string(), 0,
                            "interface id " + std::to_string(t.id) + " out of range (" +
                                std::to_string(ni) + " interfaces)");
  return d;
}

} // namespace pdd
