/// \file text.hpp
/// Implementation details of pdd's writers: locale-independent number formatting and a
/// buffered text sink that hands large blocks to a std::ostream.
#pragma once

#include <pdd/errors.hpp>

#include <charconv>
#include <concepts>
#include <cstddef>
#include <ostream>
#include <string>
#include <string_view>
#include <system_error>

namespace pdd::detail {

/// Appends the shortest decimal form of `v` that reads back to the same bits (std::to_chars),
/// e.g. "0.1", "-0", "1e-300". Locale-independent.
inline void append_double(std::string& out, double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  PDD_ASSERT(r.ec == std::errc{});
  out.append(buf, r.ptr);
}

/// Appends `v` in fixed notation with `precision` digits after the point (for SVG).
inline void append_fixed(std::string& out, double v, int precision) {
  char buf[400];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, precision);
  PDD_ASSERT(r.ec == std::errc{});
  out.append(buf, r.ptr);
}

/// Appends the decimal form of an integer.
template <std::integral I>
void append_integer(std::string& out, I v) {
  char buf[24];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  PDD_ASSERT(r.ec == std::errc{});
  out.append(buf, r.ptr);
}

/// Collects text in memory and writes it to an ostream in blocks of about `block` bytes.
/// Call flush() at the end; the destructor does not write (it must not throw).
/// Thread-safety: one object per thread.
class text_sink {
public:
  explicit text_sink(std::ostream& os, std::size_t block = std::size_t{1} << 20)
      : os_(os), block_(block) {
    buf_.reserve(block_ + 512);
  }
  text_sink(const text_sink&) = delete;
  text_sink& operator=(const text_sink&) = delete;

  text_sink& put(std::string_view s) {
    buf_.append(s);
    return maybe_flush();
  }
  text_sink& put(char c) {
    buf_.push_back(c);
    return maybe_flush();
  }
  /// Shortest round-trip form of a double.
  text_sink& num(double v) {
    append_double(buf_, v);
    return maybe_flush();
  }
  /// Fixed notation with `precision` digits after the point.
  text_sink& fixed(double v, int precision) {
    append_fixed(buf_, v, precision);
    return maybe_flush();
  }
  template <std::integral I>
  text_sink& integer(I v) {
    append_integer(buf_, v);
    return maybe_flush();
  }
  /// Writes what is buffered to the stream.
  void flush() {
    if (!buf_.empty()) os_.write(buf_.data(), static_cast<std::streamsize>(buf_.size()));
    buf_.clear();
  }

private:
  text_sink& maybe_flush() {
    if (buf_.size() >= block_) flush();
    return *this;
  }
  std::ostream& os_;
  std::size_t block_;
  std::string buf_;
};

/// Escapes the five XML special characters of an attribute value or text node.
inline std::string xml_escape(std::string_view s) {
  std::string out;
  out.reserve(s.size());
  for (const char c : s) {
    switch (c) {
    case '&':
      out += "&amp;";
      break;
    case '<':
      out += "&lt;";
      break;
    case '>':
      out += "&gt;";
      break;
    case '"':
      out += "&quot;";
      break;
    case '\'':
      out += "&apos;";
      break;
    default:
      out += c;
    }
  }
  return out;
}

} // namespace pdd::detail
