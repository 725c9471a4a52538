/// \file svg.hpp
/// Implementation details of pdd::write_svg: the viewport transform, colours and path output.
#pragma once

#include <pdd/core/point.hpp>
#include <pdd/io/detail/text.hpp>
#include <pdd/io/svg_options.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace pdd::detail {

/// Axis-aligned bounding box accumulator.
struct svg_box {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0;
  double x1 = -std::numeric_limits<double>::infinity(), y1 = x1;
  void add(point p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
    x0 = std::min(x0, p.x);
    y0 = std::min(y0, p.y);
    x1 = std::max(x1, p.x);
    y1 = std::max(y1, p.y);
  }
  bool empty() const { return !(x0 <= x1); }
};

/// Maps model coordinates to SVG pixels: uniform scale, y axis flipped, fits width_px.
class svg_canvas {
public:
  svg_canvas(text_sink& out, svg_box box, const svg_options& o) : out_(out), o_(o) {
    if (box.empty()) box = {0.0, 0.0, 1.0, 1.0};
    const double inner = std::max(1.0, o.width_px - 2.0 * o.margin_px);
    const double dx = box.x1 - box.x0, dy = box.y1 - box.y0;
    const double extent = std::max(dx, dy);
    scale_ = extent > 0.0 ? inner / (dx > 0.0 ? dx : extent) : 1.0;
    x0_ = box.x0;
    y1_ = box.y1;
    width_ = o.width_px;
    height_ = 2.0 * o.margin_px + dy * scale_;
  }
  double height() const noexcept { return height_; }

  /// Writes the SVG header; `extra_height` px are added below this canvas (an inset).
  void open(const std::string& comment, double extra_height = 0.0) {
    const double h = height_ + extra_height;
    out_.put("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    out_.put("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"");
    out_.fixed(width_, o_.precision).put("\" height=\"").fixed(h, o_.precision);
    out_.put("\" viewBox=\"0 0 ").fixed(width_, o_.precision).put(' ');
    out_.fixed(h, o_.precision).put("\">\n<!-- ").put(comment).put(" -->\n");
    out_.put("<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n");
  }
  void close() { out_.put("</svg>\n"); }
  void comment(const std::string& text) { out_.put("<!-- ").put(text).put(" -->\n"); }

  /// Writes "x y" in pixels.
  void xy(point p) { out_.fixed(x_of(p.x), o_.precision).put(' ').fixed(y_of(p.y), o_.precision); }
  void move_to(point p) {
    out_.put('M');
    xy(p);
  }
  void line_to(point p) {
    out_.put('L');
    xy(p);
  }
  /// Starts a <path>; style is the attribute list, e.g. `fill="none" stroke="#000"`.
  void begin_path(const std::string& style) { out_.put("<path ").put(style).put(" d=\""); }
  void end_path() { out_.put("\"/>\n"); }

  /// Stroked straight segments in one path.
  void segments(const std::vector<std::pair<point, point>>& segs, const std::string& colour,
                double width) {
    if (segs.empty()) return;
    begin_path(stroke_style(colour, width));
    for (const auto& [a, b] : segs) {
      move_to(a);
      line_to(b);
    }
    end_path();
  }
  /// Crosses (x) of half size hole_size_px around each point.
  void crosses(const std::vector<point>& pts, const std::string& colour) {
    if (pts.empty()) return;
    begin_path(stroke_style(colour, 1.5));
    const double h = o_.hole_size_px;
    for (const point& p : pts) {
      const double x = x_of(p.x), y = y_of(p.y);
      out_.put('M').fixed(x - h, o_.precision).put(' ').fixed(y - h, o_.precision);
      out_.put('L').fixed(x + h, o_.precision).put(' ').fixed(y + h, o_.precision);
      out_.put('M').fixed(x - h, o_.precision).put(' ').fixed(y + h, o_.precision);
      out_.put('L').fixed(x + h, o_.precision).put(' ').fixed(y - h, o_.precision);
    }
    end_path();
  }
  /// Filled dots of radius r.
  void dots(const std::vector<point>& pts, const std::string& colour, double r) {
    if (pts.empty() || r <= 0.0) return;
    out_.put("<g fill=\"").put(colour).put("\">\n");
    for (const point& p : pts) {
      out_.put("<circle cx=\"").fixed(x_of(p.x), o_.precision).put("\" cy=\"");
      out_.fixed(y_of(p.y), o_.precision).put("\" r=\"").fixed(r, o_.precision).put("\"/>\n");
    }
    out_.put("</g>\n");
  }

  static std::string stroke_style(const std::string& colour, double width) {
    std::string s = "fill=\"none\" stroke=\"" + colour + "\" stroke-width=\"";
    append_fixed(s, width, 2);
    return s + "\" stroke-linecap=\"round\" stroke-linejoin=\"round\"";
  }

private:
  double x_of(double x) const { return o_.margin_px + (x - x0_) * scale_; }
  double y_of(double y) const { return o_.margin_px + (y1_ - y) * scale_; }
  text_sink& out_;
  const svg_options& o_;
  double scale_ = 1.0, x0_ = 0.0, y1_ = 0.0, width_ = 0.0, height_ = 0.0;
};

/// Stroke colour of a boundary marker (Tableau 10 palette, cyclic).
inline std::string marker_colour(int marker) {
  static constexpr const char* palette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                            "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf"};
  return palette[((marker % 10) + 10) % 10];
}

/// A light fill colour for region/subdomain i: golden-angle hues, so neighbours in numbering
/// differ strongly.
inline std::string fill_colour(std::size_t i) {
  const double h = std::fmod(static_cast<double>(i) * 137.50776405003785, 360.0) / 60.0;
  const double s = 0.55, l = 0.75;
  const double c = (1.0 - std::abs(2.0 * l - 1.0)) * s;
  const double x = c * (1.0 - std::abs(std::fmod(h, 2.0) - 1.0));
  double r = 0, g = 0, b = 0;
  switch (static_cast<int>(h) % 6) {
  case 0:
    r = c, g = x;
    break;
  case 1:
    r = x, g = c;
    break;
  case 2:
    g = c, b = x;
    break;
  case 3:
    g = x, b = c;
    break;
  case 4:
    r = x, b = c;
    break;
  default:
    r = c, b = x;
  }
  const double m = l - c / 2.0;
  static constexpr char hex[] = "0123456789abcdef";
  std::string out = "#";
  for (const double v : {r, g, b}) {
    const int q = std::clamp(static_cast<int>(std::lround((v + m) * 255.0)), 0, 255);
    out += hex[q >> 4];
    out += hex[q & 15];
  }
  return out;
}

/// Segments grouped by marker, drawn one path per marker in increasing marker order.
using segments_by_marker = std::map<int, std::vector<std::pair<point, point>>>;

inline void draw_marked_segments(svg_canvas& c, const segments_by_marker& segs, double width) {
  for (const auto& [marker, list] : segs)
    c.segments(list, marker_colour(marker), width);
}

} // namespace pdd::detail
