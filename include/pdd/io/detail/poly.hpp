/// \file poly.hpp
/// Implementation of pdd::read_poly / parse_poly: a line tokeniser over an in-memory file and
/// a strict parser of Triangle's .poly and .node sections.
#pragma once

#include <pdd/core/point.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/errors.hpp>

#include <charconv>
#include <climits>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <istream>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace pdd::detail {

/// Splits an in-memory text into lines, drops `#` comments, splits on blanks and skips lines
/// without tokens. Line numbers are 1-based.
class line_tokenizer {
public:
  explicit line_tokenizer(std::string_view text) : text_(text) {
    if (text_.starts_with("\xEF\xBB\xBF")) pos_ = 3; // UTF-8 byte order mark
  }

  /// Advances to the next line that has at least one token; false at the end of the text.
  bool next() {
    while (pos_ < text_.size()) {
      std::size_t eol = text_.find('\n', pos_);
      if (eol == std::string_view::npos) eol = text_.size();
      std::string_view line = text_.substr(pos_, eol - pos_);
      pos_ = eol < text_.size() ? eol + 1 : eol;
      ++line_;
      if (const auto hash = line.find('#'); hash != std::string_view::npos)
        line = line.substr(0, hash);
      tokens_.clear();
      std::size_t i = 0;
      while (i < line.size()) {
        while (i < line.size() && is_blank(line[i]))
          ++i;
        const std::size_t start = i;
        while (i < line.size() && !is_blank(line[i]))
          ++i;
        if (i > start) tokens_.push_back(line.substr(start, i - start));
      }
      if (!tokens_.empty()) return true;
    }
    return false;
  }

  const std::vector<std::string_view>& tokens() const noexcept { return tokens_; }
  /// Line number of the current line (0 before the first call to next()).
  std::size_t line() const noexcept { return line_; }
  /// Bytes after the current line.
  std::size_t bytes_left() const noexcept { return text_.size() - pos_; }
  /// The line number to report when the text ends too early: its last line + 1.
  std::size_t end_line() const noexcept {
    std::size_t lines = 0;
    for (const char c : text_)
      lines += c == '\n';
    if (!text_.empty() && text_.back() != '\n') ++lines;
    return lines + 1;
  }

private:
  static bool is_blank(char c) noexcept {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
  }
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_ = 0;
  std::vector<std::string_view> tokens_;
};

/// The parsed vertex section of a .poly or .node file.
struct vertex_section {
  std::vector<point> vertices;
  std::vector<int> markers;
  std::size_t attribute_count = 0; ///< attributes per vertex
  std::vector<double> attributes;  ///< attribute_count per vertex, vertex by vertex
  long long first_id = 1;          ///< 0 or 1, from the first vertex record (Triangle's rule)
};

/// Header of a vertex section.
struct vertex_header {
  std::size_t count = 0;
  std::size_t attributes = 0;
  std::size_t markers = 0;
};

/// Strict reader of one Triangle file held in memory; every error is a pdd::input_error with
/// this file's name and the line it concerns.
class triangle_file_parser {
public:
  triangle_file_parser(std::string_view text, std::string file)
      : tok_(text), file_(std::move(file)) {}

  const std::string& file() const noexcept { return file_; }
  std::size_t line() const noexcept { return tok_.line(); }

  [[noreturn]] void fail(const std::string& message) const {
    throw input_error(file_, tok_.line(), message);
  }
  [[noreturn]] void fail_at(std::size_t line, const std::string& message) const {
    throw input_error(file_, line, message);
  }

  /// Moves to the next non-empty line; false at the end of the file.
  bool try_next() { return tok_.next(); }
  /// Moves to the next non-empty line; throws at the line after the last one if the file ends.
  /// `what()` describes the expected record; it is only called on failure.
  template <class What>
  void next(const What& what) {
    if (!tok_.next())
      fail_at(tok_.end_line(), "expected " + std::string(what()) + ", but the file ended");
  }
  /// Requires a token count in [lo, hi] on the current line.
  template <class What>
  void expect_fields(std::size_t lo, std::size_t hi, const What& what) const {
    const std::size_t n = tok_.tokens().size();
    if (n >= lo && n <= hi) return;
    const std::string want =
        lo == hi ? std::to_string(lo) : std::to_string(lo) + " or " + std::to_string(hi);
    fail("expected " + std::string(what()) + " (" + want + " fields), found " + std::to_string(n) +
         " field" + (n == 1 ? "" : "s"));
  }
  std::size_t fields() const noexcept { return tok_.tokens().size(); }

  /// Token i as an integer (optional leading '+'; the whole token must be the number).
  long long integer(std::size_t i, std::string_view what) const {
    std::string_view t = tok_.tokens()[i];
    std::string_view digits = strip_plus(t);
    long long v = 0;
    const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), v);
    if (r.ec == std::errc::result_out_of_range)
      fail("expected " + std::string(what) + " as an integer, but '" + std::string(t) +
           "' is out of range");
    if (r.ec != std::errc{} || r.ptr != digits.data() + digits.size())
      fail("expected " + std::string(what) + " as an integer, found '" + std::string(t) + "'");
    return v;
  }
  /// Token i as an int-sized integer (markers).
  int marker(std::size_t i, std::string_view what) const {
    const long long v = integer(i, what);
    if (v < INT_MIN || v > INT_MAX)
      fail("expected " + std::string(what) + " within the range of int");
    return static_cast<int>(v);
  }
  /// Token i as a finite double (std::from_chars, locale-independent).
  double real(std::size_t i, std::string_view what) const {
    std::string_view t = tok_.tokens()[i];
    std::string_view digits = strip_plus(t);
    double v = 0;
    const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), v);
    if (r.ec == std::errc::result_out_of_range)
      fail("expected " + std::string(what) + " as a number within the range of double, found '" +
           std::string(t) + "'");
    if (r.ec != std::errc{} || r.ptr != digits.data() + digits.size())
      fail("expected " + std::string(what) + " as a number, found '" + std::string(t) + "'");
    if (!std::isfinite(v))
      fail("expected " + std::string(what) + " as a finite number, found '" + std::string(t) +
           "' (NaN or infinity)");
    return v;
  }
  /// Token i as a record count: non-negative and below 2^31.
  std::size_t count(std::size_t i, std::string_view what) const {
    const long long v = integer(i, what);
    if (v < 0)
      fail("expected " + std::string(what) + " as a non-negative count, found " +
           std::to_string(v));
    if (v > std::numeric_limits<int>::max())
      fail("expected " + std::string(what) + " below 2^31, found " + std::to_string(v));
    return static_cast<std::size_t>(v);
  }
  /// Refuses a count larger than the bytes left in the file (each record needs at least one
  /// byte), so absurd counts never allocate.
  void check_fits(std::size_t n, std::string_view what) const {
    if (n > tok_.bytes_left())
      fail("expected " + std::string(what) + " that fits the rest of the file, but " +
           std::to_string(n) + " cannot fit in the remaining " + std::to_string(tok_.bytes_left()) +
           " bytes");
  }

  /// Reads "<#vertices> <dimension> <#attributes> <#boundary markers>".
  vertex_header vertex_section_header() {
    const auto what = [] {
      return "the vertex header '<#vertices> <dimension> <#attributes> <#boundary markers>'";
    };
    next(what);
    expect_fields(4, 4, what);
    vertex_header h;
    h.count = count(0, "the number of vertices");
    if (integer(1, "the dimension") != 2)
      fail("expected dimension 2, found " + std::string(tok_.tokens()[1]));
    h.attributes = count(2, "the number of vertex attributes");
    const long long m = integer(3, "the number of vertex boundary markers");
    if (m != 0 && m != 1)
      fail("expected the number of vertex boundary markers to be 0 or 1, found " +
           std::to_string(m));
    h.markers = static_cast<std::size_t>(m);
    check_fits(h.count, "the number of vertices");
    check_fits(h.attributes, "the number of vertex attributes");
    return h;
  }

  /// Reads `h.count` records "<id> <x> <y> [attributes] [marker]"; ids consecutive from 0 or 1
  /// (decided by the first record, as Triangle does). Attributes are checked and kept.
  vertex_section vertex_records(const vertex_header& h) {
    vertex_section s;
    s.vertices.reserve(h.count);
    s.markers.reserve(h.count);
    s.attribute_count = h.attributes;
    s.attributes.reserve(h.count * h.attributes);
    const std::size_t nf = 3 + h.attributes + h.markers;
    for (std::size_t i = 0; i < h.count; ++i) {
      const auto rec = [&] {
        return "vertex " + std::to_string(i + 1) + " of " + std::to_string(h.count) +
               " '<id> <x> <y>" + (h.attributes ? " <attributes>" : "") +
               (h.markers ? " <marker>" : "") + "'";
      };
      next(rec);
      expect_fields(nf, nf, rec);
      const long long id = integer(0, "the vertex id");
      if (i == 0) {
        if (id != 0 && id != 1)
          fail("expected the first vertex id to be 0 or 1, found " + std::to_string(id));
        s.first_id = id;
      } else if (id != s.first_id + static_cast<long long>(i)) {
        fail("expected vertex id " + std::to_string(s.first_id + static_cast<long long>(i)) +
             " (ids must be consecutive), found " + std::to_string(id));
      }
      const double x = real(1, "the vertex x coordinate");
      const double y = real(2, "the vertex y coordinate");
      for (std::size_t a = 0; a < h.attributes; ++a)
        s.attributes.push_back(real(3 + a, "a vertex attribute"));
      const int m = h.markers ? marker(3 + h.attributes, "the vertex boundary marker") : 0;
      s.vertices.push_back({x, y});
      s.markers.push_back(m);
    }
    return s;
  }

private:
  static std::string_view strip_plus(std::string_view t) noexcept {
    if (t.size() > 1 && t[0] == '+' && t[1] != '-' && t[1] != '+') t.remove_prefix(1);
    return t;
  }
  line_tokenizer tok_;
  std::string file_;
};

/// Reads a whole stream into a string.
inline std::string slurp(std::istream& in, const std::string& file) {
  std::string text;
  char buf[1 << 16];
  while (in.read(buf, sizeof buf) || in.gcount() > 0)
    text.append(buf, static_cast<std::size_t>(in.gcount()));
  if (in.bad()) throw error("cannot read '" + file + "': read error");
  return text;
}

/// Reads a whole file into a string.
inline std::string slurp_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw error("cannot open '" + path.string() + "' for reading");
  return slurp(in, path.string());
}

/// Reads a .node file's vertex section (the rest of the file is ignored, as Triangle does).
inline vertex_section parse_node_text(std::string_view text, const std::string& file) {
  triangle_file_parser p(text, file);
  const vertex_header h = p.vertex_section_header();
  if (h.count == 0) p.fail("expected at least one vertex in the .node file, found 0");
  return p.vertex_records(h);
}

/// Reads the vertex section of a .poly file, or the sibling .node file when its count is 0
/// (looked up in `node_dir`, or beside `file` when `node_dir` is empty).
inline vertex_section read_poly_vertices(triangle_file_parser& p, const std::string& file,
                                         const std::filesystem::path& node_dir) {
  const vertex_header h = p.vertex_section_header();
  const std::size_t header_line = p.line();
  if (h.count > 0) return p.vertex_records(h);
  const std::filesystem::path name = std::filesystem::path(file).filename();
  const std::filesystem::path dir =
      node_dir.empty() ? std::filesystem::path(file).parent_path() : node_dir;
  const std::filesystem::path node = dir / name.stem().concat(".node");
  std::error_code ec;
  if (!std::filesystem::is_regular_file(node, ec))
    p.fail_at(header_line, "expected the vertices in '" + node.string() +
                               "' (the vertex count is 0), but that file cannot be found");
  return parse_node_text(slurp_file(node), node.string());
}

/// Field `field` of the current segment record as a 0-based vertex index, given the file's
/// vertex ids [lo, hi].
inline index_t segment_endpoint(triangle_file_parser& p, std::size_t field, long long lo,
                                long long hi) {
  const long long v = p.integer(field, "a segment endpoint (vertex id)");
  if (v < 0)
    p.fail("expected a vertex id as segment endpoint, found negative index " + std::to_string(v));
  if (v < lo || v > hi)
    p.fail("expected a segment endpoint in the vertex id range [" + std::to_string(lo) + ", " +
           std::to_string(hi) + "], found " + std::to_string(v) + " (out of range)");
  return static_cast<index_t>(v - lo);
}

/// Reads the segment section of a .poly file into g.segments; vertex ids are [lo, hi].
inline void read_poly_segments(triangle_file_parser& p, long long lo, long long hi, pslg& g) {
  const auto seg_header = [] { return "the segment header '<#segments> <#boundary markers>'"; };
  p.next(seg_header);
  p.expect_fields(2, 2, seg_header);
  const std::size_t ns = p.count(0, "the number of segments");
  const long long sm = p.integer(1, "the number of segment boundary markers");
  if (sm != 0 && sm != 1)
    p.fail("expected the number of segment boundary markers to be 0 or 1, found " +
           std::to_string(sm));
  p.check_fits(ns, "the number of segments");
  g.segments.reserve(ns);
  const std::size_t snf = 3 + static_cast<std::size_t>(sm);
  for (std::size_t i = 0; i < ns; ++i) {
    const auto rec = [&] {
      return "segment " + std::to_string(i + 1) + " of " + std::to_string(ns) +
             (sm ? " '<id> <endpoint> <endpoint> <marker>'" : " '<id> <endpoint> <endpoint>'");
    };
    p.next(rec);
    p.expect_fields(snf, snf, rec);
    if (p.integer(0, "the segment id") < 0) p.fail("expected a non-negative segment id");
    const index_t a = segment_endpoint(p, 1, lo, hi);
    const index_t b = segment_endpoint(p, 2, lo, hi);
    const int m = sm ? p.marker(3, "the segment boundary marker") : 0;
    g.segments.push_back({a, b, m});
  }
}

/// Reads the (required) hole section of a .poly file into g.holes.
inline void read_poly_holes(triangle_file_parser& p, pslg& g) {
  const auto hole_header = [] { return "the hole header '<#holes>'"; };
  p.next(hole_header);
  p.expect_fields(1, 1, hole_header);
  const std::size_t nh = p.count(0, "the number of holes");
  p.check_fits(nh, "the number of holes");
  g.holes.reserve(nh);
  for (std::size_t i = 0; i < nh; ++i) {
    const auto rec = [&] {
      return "hole " + std::to_string(i + 1) + " of " + std::to_string(nh) + " '<id> <x> <y>'";
    };
    p.next(rec);
    p.expect_fields(3, 3, rec);
    if (p.integer(0, "the hole id") < 0) p.fail("expected a non-negative hole id");
    g.holes.push_back({p.real(1, "the hole x coordinate"), p.real(2, "the hole y coordinate")});
  }
}

/// Reads the optional regional attribute section of a .poly file into g.regions, then
/// requires the end of the file.
inline void read_poly_regions(triangle_file_parser& p, pslg& g) {
  if (!p.try_next()) return;
  p.expect_fields(1, 1, [] { return "the regional attribute header '<#regions>'"; });
  const std::size_t nr = p.count(0, "the number of regions");
  p.check_fits(nr, "the number of regions");
  g.regions.reserve(nr);
  for (std::size_t i = 0; i < nr; ++i) {
    const auto rec = [&] {
      return "region " + std::to_string(i + 1) + " of " + std::to_string(nr) +
             " '<id> <x> <y> <attribute> [<maximum area>]'";
    };
    p.next(rec);
    p.expect_fields(4, 5, rec);
    if (p.integer(0, "the region id") < 0) p.fail("expected a non-negative region id");
    region r;
    r.p = {p.real(1, "the region x coordinate"), p.real(2, "the region y coordinate")};
    r.attribute = p.real(3, "the regional attribute");
    // Without a fifth field Triangle 1.6 takes the fourth as the area bound too (triangle.c,
    // readholes: regionlist[index] = regionlist[index - 1]); the triangle package's la.poly
    // relies on it for -pqa. A bound <= 0 is no bound, as in Triangle.
    r.max_area = p.fields() == 5 ? p.real(4, "the region's maximum area") : r.attribute;
    g.regions.push_back(r);
  }
  if (p.try_next()) p.fail("expected the end of the file after the regional attributes");
}

/// Parses a .poly file held in memory; see pdd::parse_poly.
inline pslg parse_poly_text(std::string_view text, const std::string& file,
                            const std::filesystem::path& node_dir) {
  triangle_file_parser p(text, file);
  pslg g;
  vertex_section vs = read_poly_vertices(p, file, node_dir);
  g.vertices = std::move(vs.vertices);
  g.vertex_markers = std::move(vs.markers);
  g.vertex_attribute_count = vs.attribute_count;
  g.vertex_attributes = std::move(vs.attributes);
  const long long lo = vs.first_id;
  const long long hi = lo + static_cast<long long>(g.vertices.size()) - 1;
  read_poly_segments(p, lo, hi, g);
  read_poly_holes(p, g);
  read_poly_regions(p, g);
  return g;
}

} // namespace pdd::detail
