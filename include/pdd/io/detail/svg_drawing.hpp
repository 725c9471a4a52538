/// \file svg_drawing.hpp
/// Implementation of pdd::write_svg: input checks and the drawing of a PSLG and of a mesh
/// on an svg_canvas.
#pragma once

#include <pdd/core/decomposition.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/errors.hpp>
#include <pdd/io/detail/mesh_picture.hpp>
#include <pdd/io/detail/svg.hpp>
#include <pdd/io/svg_options.hpp>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace pdd::detail {

inline void check_svg_pslg(const pslg& g, const std::filesystem::path& path) {
  for (std::size_t i = 0; i < g.segments.size(); ++i)
    if (g.segments[i].a >= g.vertices.size() || g.segments[i].b >= g.vertices.size())
      throw error("cannot write '" + path.string() + "': segment " + std::to_string(i) +
                  " refers to a missing vertex");
}

inline svg_box pslg_box(const pslg& g) {
  svg_box b;
  for (const point& p : g.vertices)
    b.add(p);
  for (const point& p : g.holes)
    b.add(p);
  for (const region& r : g.regions)
    b.add(r.p);
  return b;
}

/// Draws g's segments (coloured by marker), vertices, hole crosses and region points.
inline void draw_pslg(svg_canvas& c, const pslg& g, const svg_options& o) {
  segments_by_marker segs;
  for (const segment& s : g.segments)
    segs[s.marker].emplace_back(g.vertices[s.a], g.vertices[s.b]);
  draw_marked_segments(c, segs, o.segment_stroke_px);
  c.dots(g.vertices, "#000000", o.vertex_radius_px);
  c.crosses(g.holes, "#ff0000");
  std::vector<point> regions;
  for (const region& r : g.regions)
    regions.push_back(r.p);
  c.dots(regions, "#1f77b4", 2.0 * o.vertex_radius_px);
}

/// Fills the triangles of each marker in its own colour (nothing for a single marker).
inline void fill_triangles_by_marker(svg_canvas& c, const triangle_mesh& m) {
  std::map<int, std::vector<std::size_t>> by_marker;
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    by_marker[m.triangle_markers.empty() ? 0 : m.triangle_markers[t]].push_back(t);
  if (by_marker.size() <= 1) return;
  std::size_t k = 0;
  for (const auto& [marker, tris] : by_marker) {
    c.begin_path("fill=\"" + fill_colour(k++) + "\" stroke=\"none\"");
    for (const std::size_t t : tris) {
      c.move_to(m.vertices[m.triangles[t][0]]);
      c.line_to(m.vertices[m.triangles[t][1]]);
      c.line_to(m.vertices[m.triangles[t][2]]);
    }
    c.end_path();
  }
}

/// Draws every edge of the mesh once (thin grey), in the order of their endpoint ids.
inline void draw_mesh_edges(svg_canvas& c, const triangle_mesh& m, const svg_options& o) {
  std::vector<std::uint64_t> edges;
  edges.reserve(3 * m.triangles.size());
  for (const auto& t : m.triangles)
    for (int i = 0; i < 3; ++i) {
      const std::uint64_t a = t[i], b = t[(i + 1) % 3];
      edges.push_back(a < b ? (a << 32 | b) : (b << 32 | a));
    }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  if (edges.empty()) return;
  c.begin_path(svg_canvas::stroke_style("#555555", o.mesh_stroke_px));
  for (const std::uint64_t e : edges) {
    c.move_to(m.vertices[e >> 32]);
    c.line_to(m.vertices[e & 0xffffffffu]);
  }
  c.end_path();
}

/// Draws the mesh: triangles filled by marker when there are several markers, every edge once
/// (thin), then the boundary segments by marker; above max_triangles the subdomains filled and
/// the separators instead of the triangles.
inline void draw_mesh(svg_canvas& c, const triangle_mesh& m, const svg_options& o) {
  if (m.triangles.size() > o.max_triangles) {
    c.comment("the mesh has " + std::to_string(m.triangles.size()) +
              " triangles, more than max_triangles = " + std::to_string(o.max_triangles) +
              ": its subdomains are drawn filled, with the separators, not its triangles");
    draw_subdomains(c, m, classify_edges(m), o);
  } else {
    fill_triangles_by_marker(c, m);
    if (o.shade_by_area) shade_triangles_by_area(c, m, o);
    draw_mesh_edges(c, m, o);
  }
  segments_by_marker segs;
  for (const mesh_edge& e : m.segments)
    segs[e.marker].emplace_back(m.vertices[e.a], m.vertices[e.b]);
  draw_marked_segments(c, segs, o.segment_stroke_px);
}

inline void check_decomposition(const decomposition& d, const std::filesystem::path& path) {
  const std::string where = "cannot write '" + path.string() + "': ";
  for (std::size_t s = 0; s < d.subdomains.size(); ++s) {
    const subdomain& sd = d.subdomains[s];
    if (sd.tags.size() != sd.loops.size())
      throw error(where + "subdomain " + std::to_string(s) +
                  " has loops and tags of different "
                  "counts");
    for (std::size_t l = 0; l < sd.loops.size(); ++l) {
      if (sd.tags[l].size() != sd.loops[l].size())
        throw error(where + "subdomain " + std::to_string(s) + " loop " + std::to_string(l) +
                    " has " + std::to_string(sd.loops[l].size()) + " vertices but " +
                    std::to_string(sd.tags[l].size()) + " edge tags");
      for (const index_t v : sd.loops[l])
        if (v >= d.vertices.size())
          throw error(where + "subdomain " + std::to_string(s) + " refers to missing vertex " +
                      std::to_string(v));
    }
  }
}

} // namespace pdd::detail
