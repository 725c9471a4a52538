/// \file mesh_picture.hpp
/// Implementation of pdd::write_svg for meshes of any size: the outline of every subdomain
/// (marker) and the separators between subdomains found from the triangles, the zoomed inset
/// and the legend.
#pragma once

#include <pdd/core/triangle_measures.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/io/detail/svg.hpp>
#include <pdd/io/svg_options.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace pdd::detail {

/// The edges a picture of a marked mesh needs: separators (edges between triangles of
/// different markers, once each) and, per marker, the directed boundary edges of its region
/// (counter-clockwise around it, so the region is their nonzero fill).
struct marked_edges {
  std::vector<std::pair<index_t, index_t>> separators;
  std::map<int, std::vector<std::pair<index_t, index_t>>> outline;
};

/// Classifies the edges of m (sorting 3 t edge records). Complexity O(t log t), about 48
/// bytes per triangle of working memory.
inline marked_edges classify_edges(const triangle_mesh& m) {
  struct rec {
    std::uint64_t key;
    int marker;
    index_t from, to;
  };
  std::vector<rec> r;
  r.reserve(3 * m.triangles.size());
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const index_t a = m.triangles[t][static_cast<std::size_t>(i)];
      const index_t b = m.triangles[t][static_cast<std::size_t>((i + 1) % 3)];
      const std::uint64_t k = a < b ? (std::uint64_t{a} << 32 | b) : (std::uint64_t{b} << 32 | a);
      r.push_back({k, m.triangle_markers.empty() ? 0 : m.triangle_markers[t], a, b});
    }
  std::sort(r.begin(), r.end(), [](const rec& x, const rec& y) { return x.key < y.key; });
  marked_edges out;
  for (std::size_t i = 0; i < r.size();) {
    const bool paired = i + 1 < r.size() && r[i + 1].key == r[i].key;
    if (paired && r[i].marker == r[i + 1].marker) {
      i += 2;
      continue;
    }
    if (paired) out.separators.emplace_back(r[i].from, r[i].to);
    for (std::size_t j = i; j < i + (paired ? 2 : 1); ++j)
      out.outline[r[j].marker].emplace_back(r[j].from, r[j].to);
    i += paired ? 2 : 1;
  }
  return out;
}

/// Draws directed boundary edges as closed loops in one filled path (nonzero rule): each
/// edge is followed by an unused edge leaving its end vertex.
inline void fill_outline(svg_canvas& c, const triangle_mesh& m,
                         std::vector<std::pair<index_t, index_t>> edges, const std::string& fill) {
  std::sort(edges.begin(), edges.end());
  std::vector<char> used(edges.size(), 0);
  c.begin_path("fill=\"" + fill + "\" stroke=\"none\" fill-rule=\"nonzero\"");
  for (std::size_t s = 0; s < edges.size(); ++s) {
    if (used[s]) continue;
    c.move_to(m.vertices[edges[s].first]);
    std::size_t e = s;
    while (!used[e]) {
      used[e] = 1;
      c.line_to(m.vertices[edges[e].second]);
      auto it = std::lower_bound(edges.begin(), edges.end(),
                                 std::pair<index_t, index_t>{edges[e].second, 0});
      while (it != edges.end() && it->first == edges[e].second && used[it - edges.begin()])
        ++it;
      if (it == edges.end() || it->first != edges[e].second) break;
      e = static_cast<std::size_t>(it - edges.begin());
    }
  }
  c.end_path();
}

/// The fill colour of every marker: its rank among the markers (as in small pictures).
inline std::map<int, std::string> marker_fills(const triangle_mesh& m) {
  std::map<int, std::string> fills;
  for (const int k : m.triangle_markers)
    fills.emplace(k, std::string());
  if (fills.empty()) fills.emplace(0, std::string());
  std::size_t rank = 0;
  for (auto& f : fills)
    f.second = fill_colour(rank++);
  return fills;
}

/// Sum of the triangle areas.
inline double mesh_area(const triangle_mesh& m) {
  double a = 0.0;
  for (const auto& t : m.triangles) {
    const point p = m.vertices[t[0]], q = m.vertices[t[1]], r = m.vertices[t[2]];
    a += triangle_area(p, q, r);
  }
  return a;
}

/// Triangle centroids counted on a grid of square cells (for choosing the inset).
struct centroid_grid {
  double x0 = 0, y0 = 0, cell = 1;
  std::size_t nx = 0, ny = 0;
  std::vector<std::size_t> count;

  centroid_grid(const triangle_mesh& m, const svg_box& box, double side)
      : x0(box.x0), y0(box.y0), cell(side),
        nx(static_cast<std::size_t>((box.x1 - box.x0) / side) + 1),
        ny(static_cast<std::size_t>((box.y1 - box.y0) / side) + 1), count(nx * ny, 0) {
    for (const auto& t : m.triangles) {
      const point a = m.vertices[t[0]], b = m.vertices[t[1]], c = m.vertices[t[2]];
      ++count[at((a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3)];
    }
  }
  std::size_t at(double x, double y) const {
    const auto i = std::min(nx - 1, static_cast<std::size_t>(std::max(0.0, (x - x0) / cell)));
    const auto j = std::min(ny - 1, static_cast<std::size_t>(std::max(0.0, (y - y0) / cell)));
    return j * nx + i;
  }
  /// Centroids in the cells that the square of half side `half` around p touches.
  std::size_t around(point p, double half) const {
    const std::size_t lo = at(p.x - half, p.y - half), hi = at(p.x + half, p.y + half);
    std::size_t n = 0;
    for (std::size_t j = lo / nx; j <= hi / nx; ++j)
      for (std::size_t i = lo % nx; i <= hi % nx; ++i)
        n += count[j * nx + i];
    return n;
  }
};

/// The automatic inset: a square that holds about o.inset_triangles triangles when full,
/// centred on a separator vertex (on the mesh's centre without separators): among 64
/// separator vertices spread over the separators, the one whose square holds the most
/// triangles (the least hole or outside), the one nearest the centre among equals.
/// Complexity O(t).
inline svg_window automatic_window(const triangle_mesh& m, const marked_edges& e,
                                   const svg_box& box, const svg_options& o) {
  const point centre{(box.x0 + box.x1) / 2, (box.y0 + box.y1) / 2};
  const double per =
      mesh_area(m) / static_cast<double>(std::max<std::size_t>(1, m.triangles.size()));
  const double h = 0.5 * std::sqrt(static_cast<double>(o.inset_triangles) * per);
  point at = centre;
  const double cells = ((box.x1 - box.x0) / h + 1) * ((box.y1 - box.y0) / h + 1);
  if (!e.separators.empty() && h > 0.0 && cells < 1e7) {
    const centroid_grid grid(m, box, h);
    std::size_t best = 0;
    double nearest = INFINITY;
    for (std::size_t k = 0; k < 64; ++k) {
      const point p = m.vertices[e.separators[k * e.separators.size() / 64].first];
      const std::size_t n = grid.around(p, h);
      const double d = std::hypot(p.x - centre.x, p.y - centre.y);
      if (n > best || (n == best && d < nearest)) best = n, nearest = d, at = p;
    }
  }
  return {at.x - h, at.y - h, at.x + h, at.y + h};
}

/// The separators as point pairs.
inline std::vector<std::pair<point, point>> separator_segments(const triangle_mesh& m,
                                                               const marked_edges& e) {
  std::vector<std::pair<point, point>> seps;
  seps.reserve(e.separators.size());
  for (const auto& s : e.separators)
    seps.emplace_back(m.vertices[s.first], m.vertices[s.second]);
  return seps;
}

/// The angles of a mesh: extremes and 1-degree bins (core/triangle_measures.hpp's angles,
/// the values pdd::compute_statistics reports).
struct angle_summary {
  double min_deg = 0.0, max_deg = 0.0;
  std::array<std::size_t, 180> bins{};
};
inline angle_summary summarize_angles(const triangle_mesh& m) {
  angle_summary a;
  a.min_deg = m.triangles.empty() ? 0.0 : 180.0;
  for (const auto& t : m.triangles)
    for (const double d :
         triangle_angles_deg(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]])) {
      a.min_deg = std::min(a.min_deg, d);
      a.max_deg = std::max(a.max_deg, d);
      ++a.bins[std::min<std::size_t>(179, static_cast<std::size_t>(std::max(0.0, d)))];
    }
  return a;
}

/// The legend lines: triangles and vertices, subdomains, smallest angle.
inline std::vector<std::string> legend_lines(const triangle_mesh& m) {
  const angle_summary q = summarize_angles(m);
  std::map<int, char> markers;
  for (const int k : m.triangle_markers)
    markers.emplace(k, 0);
  std::string angle;
  append_fixed(angle, q.min_deg, 2);
  return {std::to_string(m.triangles.size()) + " triangles, " + std::to_string(m.vertices.size()) +
              " vertices",
          std::to_string(std::max<std::size_t>(1, markers.size())) + " subdomain(s)",
          "smallest angle " + angle + " deg"};
}

/// The smallest and largest triangle area of m (0, 0 without triangles).
inline std::pair<double, double> area_extremes(const triangle_mesh& m) {
  if (m.triangles.empty()) return {0.0, 0.0};
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (const auto& t : m.triangles) {
    const double a = triangle_area(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]);
    lo = std::min(lo, a);
    hi = std::max(hi, a);
  }
  return {lo, hi};
}

/// Shades every triangle by log(area) in o.area_shades steps: black at opacity 0.5 for the
/// smallest step down to none for the largest, one path per step.
inline void shade_triangles_by_area(svg_canvas& c, const triangle_mesh& m, const svg_options& o) {
  const auto [lo, hi] = area_extremes(m);
  const int steps = std::max(2, o.area_shades);
  if (!(lo > 0.0) || !(hi > lo)) return;
  const double span = std::log(hi / lo);
  std::vector<std::vector<std::size_t>> by_step(static_cast<std::size_t>(steps));
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto& tr = m.triangles[t];
    const double a = triangle_area(m.vertices[tr[0]], m.vertices[tr[1]], m.vertices[tr[2]]);
    const double u = a > 0.0 ? std::log(a / lo) / span : 0.0;
    by_step[static_cast<std::size_t>(std::clamp(u * steps, 0.0, steps - 1.0))].push_back(t);
  }
  for (int k = 0; k + 1 < steps; ++k) {
    if (by_step[k].empty()) continue;
    std::string opacity;
    append_fixed(opacity, 0.5 * (1.0 - double(k) / double(steps - 1)), 3);
    c.begin_path("fill=\"#000000\" fill-opacity=\"" + opacity + "\" stroke=\"none\"");
    for (const std::size_t t : by_step[k]) {
      c.move_to(m.vertices[m.triangles[t][0]]);
      c.line_to(m.vertices[m.triangles[t][1]]);
      c.line_to(m.vertices[m.triangles[t][2]]);
    }
    c.end_path();
  }
}

/// The legend line of the area shading.
inline std::string shading_legend(const triangle_mesh& m) {
  const auto [lo, hi] = area_extremes(m);
  char buf[160];
  std::snprintf(buf, sizeof buf, "shade: triangle area %.3g (darkest) to %.3g (none), log scale",
                lo, hi);
  return buf;
}

/// Writes text lines in a white box at pixel (x, y).
inline void legend_box(text_sink& out, double x, double y, const std::vector<std::string>& lines) {
  out.put("<g font-family=\"sans-serif\" font-size=\"14\">\n<rect x=\"").fixed(x, 1);
  std::size_t longest = 0;
  for (const std::string& l : lines)
    longest = std::max(longest, l.size());
  out.put("\" y=\"").fixed(y, 1).put("\" width=\"");
  out.fixed(16.0 + 8.0 * static_cast<double>(longest), 1).put("\" height=\"");
  out.fixed(8.0 + 18.0 * static_cast<double>(lines.size()), 1);
  out.put("\" fill=\"#ffffff\" fill-opacity=\"0.85\" stroke=\"#888888\"/>\n");
  for (std::size_t i = 0; i < lines.size(); ++i) {
    out.put("<text x=\"").fixed(x + 8.0, 1).put("\" y=\"");
    out.fixed(y + 18.0 * static_cast<double>(i + 1), 1).put("\">").put(lines[i]);
    out.put("</text>\n");
  }
  out.put("</g>\n");
}

/// Fills each marker's region, draws the separators (black) and the boundary segments (by
/// marker): the picture of a mesh too large to draw triangle by triangle.
inline void draw_subdomains(svg_canvas& c, const triangle_mesh& m, const marked_edges& e,
                            const svg_options& o) {
  const auto fills = marker_fills(m);
  for (const auto& [marker, edges] : e.outline)
    fill_outline(c, m, edges, fills.at(marker));
  c.segments(separator_segments(m, e), "#000000", o.segment_stroke_px);
}

/// Draws the triangles that meet window w (filled by marker, edges thin), the separators and
/// the boundary segments among them; the caller clips to w.
inline void draw_window_triangles(svg_canvas& c, const triangle_mesh& m, const marked_edges& e,
                                  const svg_window& w, const svg_options& o) {
  const auto meets = [&w](point a, point b, point d) {
    return std::max({a.x, b.x, d.x}) >= w.x0 && std::min({a.x, b.x, d.x}) <= w.x1 &&
           std::max({a.y, b.y, d.y}) >= w.y0 && std::min({a.y, b.y, d.y}) <= w.y1;
  };
  const auto fills = marker_fills(m);
  std::map<int, std::vector<std::size_t>> shown;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto& v = m.triangles[t];
    if (meets(m.vertices[v[0]], m.vertices[v[1]], m.vertices[v[2]]))
      shown[m.triangle_markers.empty() ? 0 : m.triangle_markers[t]].push_back(t);
  }
  for (const auto& [marker, tris] : shown) {
    c.begin_path("fill=\"" + fills.at(marker) + "\" stroke=\"#555555\" stroke-width=\"" +
                 std::to_string(o.mesh_stroke_px) + "\" stroke-linejoin=\"round\"");
    for (const std::size_t t : tris) {
      c.move_to(m.vertices[m.triangles[t][0]]);
      c.line_to(m.vertices[m.triangles[t][1]]);
      c.line_to(m.vertices[m.triangles[t][2]]);
      c.line_to(m.vertices[m.triangles[t][0]]);
    }
    c.end_path();
  }
  const auto inside = [&w](point p) {
    return p.x >= w.x0 && p.x <= w.x1 && p.y >= w.y0 && p.y <= w.y1;
  };
  std::vector<std::pair<point, point>> seps;
  for (const auto& s : e.separators)
    if (inside(m.vertices[s.first]) || inside(m.vertices[s.second]))
      seps.emplace_back(m.vertices[s.first], m.vertices[s.second]);
  c.segments(seps, "#000000", o.segment_stroke_px);
  segments_by_marker segs;
  for (const mesh_edge& b : m.segments)
    if (inside(m.vertices[b.a]) || inside(m.vertices[b.b]))
      segs[b.marker].emplace_back(m.vertices[b.a], m.vertices[b.b]);
  draw_marked_segments(c, segs, o.segment_stroke_px);
}

/// The window's frame on the picture (red), then below it the inset: the window's triangles
/// clipped to it, on its own canvas, with a caption.
inline void draw_inset(text_sink& out, svg_canvas& main, svg_canvas& inset, const triangle_mesh& m,
                       const marked_edges& e, const svg_window& w, const svg_options& o) {
  main.begin_path(svg_canvas::stroke_style("#d62728", 2.0));
  main.move_to({w.x0, w.y0});
  main.line_to({w.x1, w.y0});
  main.line_to({w.x1, w.y1});
  main.line_to({w.x0, w.y1});
  main.line_to({w.x0, w.y0});
  main.end_path();
  out.put("<g transform=\"translate(0 ").fixed(main.height(), 2).put(")\">\n");
  out.put("<clipPath id=\"pdd-inset\"><rect x=\"").fixed(o.margin_px, 2).put("\" y=\"");
  out.fixed(o.margin_px, 2).put("\" width=\"").fixed(o.width_px - 2 * o.margin_px, 2);
  out.put("\" height=\"").fixed(inset.height() - 2 * o.margin_px, 2).put("\"/></clipPath>\n");
  out.put("<g clip-path=\"url(#pdd-inset)\">\n");
  draw_window_triangles(inset, m, e, w, o);
  out.put("</g>\n");
  std::string caption = "inset: x ";
  append_fixed(caption, w.x0, 4);
  caption += " to ";
  append_fixed(caption, w.x1, 4);
  caption += ", y ";
  append_fixed(caption, w.y0, 4);
  caption += " to ";
  append_fixed(caption, w.y1, 4);
  out.put("<rect x=\"").fixed(o.margin_px, 2).put("\" y=\"").fixed(o.margin_px, 2);
  out.put("\" width=\"").fixed(o.width_px - 2 * o.margin_px, 2).put("\" height=\"");
  out.fixed(inset.height() - 2 * o.margin_px, 2);
  out.put("\" fill=\"none\" stroke=\"#d62728\" stroke-width=\"2\"/>\n");
  legend_box(out, o.margin_px + 4, o.margin_px + 4, {caption});
  out.put("</g>\n");
}

} // namespace pdd::detail
