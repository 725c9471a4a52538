/// \file decomposition_io.hpp
/// Implementation of pdd::write_decomposition and pdd::read_decomposition: the shortest
/// round-trip number output, the line and token reader with file:line errors, and the readers
/// of the format's sections.
#pragma once

#include <pdd/core/decomposition.hpp>
#include <pdd/errors.hpp>

#include <charconv>
#include <cmath>
#include <istream>
#include <ostream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace pdd::detail {

inline void put_double(std::ostream& os, double v) {
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  os.write(buf, r.ptr - buf);
}

/// Reads a decomposition file line by line, splitting each line into tokens.
class decomposition_reader {
public:
  decomposition_reader(std::istream& in, std::string file) : in_(in), file_(std::move(file)) {}

  /// Advances to the next non-empty line (comments removed); throws at end of file.
  void next(const char* expected) {
    std::string line;
    while (std::getline(in_, line)) {
      ++line_;
      if (auto h = line.find('#'); h != std::string::npos) line.resize(h);
      tokens_.clear();
      std::istringstream ss(line);
      for (std::string t; ss >> t;)
        tokens_.push_back(t);
      if (!tokens_.empty()) return;
    }
    ++line_; // the line that is missing
    fail(std::string("unexpected end of file, expected ") + expected);
  }
  void expect_count(std::size_t n, const char* what) const {
    if (tokens_.size() != n)
      fail("expected " + std::to_string(n) + " fields (" + what + "), found " +
           std::to_string(tokens_.size()));
  }
  void expect_keyword(std::size_t i, std::string_view kw) const {
    if (i >= tokens_.size() || tokens_[i] != kw) fail("expected '" + std::string(kw) + "'");
  }
  std::size_t size() const { return tokens_.size(); }
  const std::string& token(std::size_t i) const { return tokens_.at(i); }

  double real(std::size_t i) const {
    double v = 0;
    const std::string& t = tokens_.at(i);
    const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if (r.ec != std::errc{} || r.ptr != t.data() + t.size() || !std::isfinite(v))
      fail("expected a finite number, found '" + t + "'");
    return v;
  }
  template <class Int>
  Int integer(std::size_t i, Int max_value) const {
    long long v = 0;
    const std::string& t = tokens_.at(i);
    const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if (r.ec != std::errc{} || r.ptr != t.data() + t.size())
      fail("expected an integer, found '" + t + "'");
    if (v < 0 || static_cast<unsigned long long>(v) > static_cast<unsigned long long>(max_value))
      fail("value " + t + " out of range 0.." + std::to_string(max_value));
    return static_cast<Int>(v);
  }
  int marker(std::size_t i) const {
    long long v = 0;
    const std::string& t = tokens_.at(i);
    const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
    if (r.ec != std::errc{} || r.ptr != t.data() + t.size() || v < INT32_MIN || v > INT32_MAX)
      fail("expected an integer marker, found '" + t + "'");
    return static_cast<int>(v);
  }
  [[noreturn]] void fail(const std::string& what) const { throw input_error(file_, line_, what); }

private:
  std::istream& in_;
  std::string file_;
  std::size_t line_ = 0;
  std::vector<std::string> tokens_;
};

/// Largest count read_decomposition accepts for any section.
inline constexpr index_t max_decomposition_count = 1u << 30;

/// Reads the header line and the vertex section into d.
inline void read_decomposition_vertices(decomposition_reader& r, decomposition& d) {
  r.next("'pdd-decomposition 1'");
  r.expect_keyword(0, "pdd-decomposition");
  r.expect_count(2, "pdd-decomposition VERSION");
  if (r.token(1) != "1" && r.token(1) != "2")
    r.fail("unsupported version '" + r.token(1) + "', expected 1 or 2");
  r.next("'vertices <n>'");
  r.expect_keyword(0, "vertices");
  r.expect_count(2, "vertices <n>");
  const index_t nv = r.integer<index_t>(1, max_decomposition_count);
  for (index_t i = 0; i < nv; ++i) {
    r.next("a vertex line '<x> <y> <marker>'");
    r.expect_count(3, "<x> <y> <marker>");
    d.vertices.push_back({r.real(0), r.real(1)});
    d.vertex_markers.push_back(r.marker(2));
  }
}

/// Reads one edge line of a loop: appends its vertex (< nv) and its tag (neighbours < ns).
inline void read_decomposition_edge(decomposition_reader& r, index_t nv, index_t ns,
                                    std::vector<index_t>& loop, std::vector<edge_tag>& tags) {
  r.next("an edge line '<vertex> e|i|s <id> <marker|neighbour> [<marker>]'");
  if (r.size() > 1 && r.token(1) == "s")
    r.expect_count(5, "<vertex> s <interface id> <neighbour> <marker>");
  else
    r.expect_count(4, "<vertex> e|i <id> <marker|neighbour>");
  loop.push_back(r.integer<index_t>(0, nv - 1));
  edge_tag t;
  if (r.token(1) == "s") {
    t.type = edge_tag::kind::interface;
    t.id = r.integer<index_t>(2, max_decomposition_count);
    t.neighbour = r.integer<index_t>(3, ns - 1);
    t.on_segment = true;
    t.marker = r.marker(4);
  } else if (r.token(1) == "e") {
    t.type = edge_tag::kind::external;
    t.id = r.integer<index_t>(2, max_decomposition_count);
    t.marker = r.marker(3);
  } else if (r.token(1) == "i") {
    t.type = edge_tag::kind::interface;
    t.id = r.integer<index_t>(2, max_decomposition_count);
    t.neighbour = r.integer<index_t>(3, ns - 1);
  } else {
    r.fail("expected 'e' (external), 'i' (interface) or 's' (interface on a segment), found '" +
           r.token(1) + "'");
  }
  tags.push_back(t);
}

/// Reads one inner constraint line ('segment <a> <b> <segment id> <marker>' or 'vertex <a>').
inline inner_constraint read_inner_constraint(decomposition_reader& r, index_t nv) {
  r.next("an inner constraint line 'segment <a> <b> <segment id> <marker>' or 'vertex <a>'");
  inner_constraint c;
  if (r.size() > 0 && r.token(0) == "vertex") {
    r.expect_count(2, "vertex <a>");
    c.a = c.b = r.integer<index_t>(1, nv - 1);
    return c;
  }
  r.expect_keyword(0, "segment");
  r.expect_count(5, "segment <a> <b> <segment id> <marker>");
  c.a = r.integer<index_t>(1, nv - 1);
  c.b = r.integer<index_t>(2, nv - 1);
  c.segment = r.integer<index_t>(3, max_decomposition_count);
  c.marker = r.marker(4);
  if (c.a == c.b) r.fail("an inner segment needs two different vertices");
  return c;
}

/// Writes one loop edge line: external, interface, or interface on an input segment.
inline void put_decomposition_edge(std::ostream& os, index_t v, const edge_tag& t) {
  os << v;
  if (t.type == edge_tag::kind::external)
    os << " e " << t.id << ' ' << t.marker << '\n';
  else if (t.on_segment)
    os << " s " << t.id << ' ' << t.neighbour << ' ' << t.marker << '\n';
  else
    os << " i " << t.id << ' ' << t.neighbour << '\n';
}

/// Reads one subdomain (its header line and its loops); nv vertices, ns subdomains.
inline subdomain read_decomposition_subdomain(decomposition_reader& r, index_t nv, index_t ns) {
  r.next("'subdomain <area> <loops> [<inner>]'");
  r.expect_keyword(0, "subdomain");
  if (r.size() != 4) r.expect_count(3, "subdomain <area> <loops> [<inner>]");
  subdomain sd;
  sd.area = r.real(1);
  const index_t nl = r.integer<index_t>(2, max_decomposition_count);
  const index_t ni = r.size() == 4 ? r.integer<index_t>(3, max_decomposition_count) : 0;
  if (nl == 0) r.fail("a subdomain needs at least one loop");
  for (index_t l = 0; l < nl; ++l) {
    r.next("'loop <edges>'");
    r.expect_keyword(0, "loop");
    r.expect_count(2, "loop <edges>");
    const index_t ne = r.integer<index_t>(1, max_decomposition_count);
    if (ne < 3) r.fail("a loop needs at least 3 edges");
    std::vector<index_t> loop;
    std::vector<edge_tag> tags;
    for (index_t e = 0; e < ne; ++e)
      read_decomposition_edge(r, nv, ns, loop, tags);
    sd.loops.push_back(std::move(loop));
    sd.tags.push_back(std::move(tags));
  }
  for (index_t i = 0; i < ni; ++i)
    sd.inner.push_back(read_inner_constraint(r, nv));
  return sd;
}

/// Reads the subdomain section into d.subdomains (after the vertices).
inline void read_decomposition_subdomains(decomposition_reader& r, decomposition& d) {
  const auto nv = static_cast<index_t>(d.vertices.size());
  r.next("'subdomains <m>'");
  r.expect_keyword(0, "subdomains");
  r.expect_count(2, "subdomains <m>");
  const index_t ns = r.integer<index_t>(1, max_decomposition_count);
  if (ns > 0 && nv < 3) r.fail("subdomains need at least 3 vertices");
  for (index_t s = 0; s < ns; ++s)
    d.subdomains.push_back(read_decomposition_subdomain(r, nv, ns));
}

/// Reads the interface section into d.interfaces (after the subdomains).
inline void read_decomposition_interfaces(decomposition_reader& r, decomposition& d) {
  const auto nv = static_cast<index_t>(d.vertices.size());
  const auto ns = static_cast<index_t>(d.subdomains.size());
  r.next("'interfaces <k>'");
  r.expect_keyword(0, "interfaces");
  r.expect_count(2, "interfaces <k>");
  const index_t ni = r.integer<index_t>(1, max_decomposition_count);
  for (index_t i = 0; i < ni; ++i) {
    r.next("an interface line '<a> <b> <n> <v0> ...'");
    if (r.size() < 5) r.fail("expected '<a> <b> <n> <v0> <v1> ...' with n >= 2");
    interface_curve c;
    if (ns == 0) r.fail("an interface needs subdomains");
    c.a = r.integer<index_t>(0, ns - 1);
    c.b = r.integer<index_t>(1, ns - 1);
    const index_t n = r.integer<index_t>(2, max_decomposition_count);
    r.expect_count(3 + n, "<a> <b> <n> followed by n vertex ids");
    for (index_t k = 0; k < n; ++k)
      c.vertices.push_back(r.integer<index_t>(3 + k, nv - 1));
    d.interfaces.push_back(std::move(c));
  }
}

} // namespace pdd::detail
