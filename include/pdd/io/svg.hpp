/// \file svg.hpp
/// pdd::write_svg: SVG pictures of a PSLG, a triangle mesh (optionally with its PSLG on top)
/// and a MADD decomposition, for inspection in a browser.
#pragma once

#include <pdd/core/decomposition.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/errors.hpp>
#include <pdd/io/atomic_file.hpp>
#include <pdd/io/detail/mesh.hpp>
#include <pdd/io/detail/mesh_picture.hpp>
#include <pdd/io/detail/svg.hpp>
#include <pdd/io/detail/svg_drawing.hpp>
#include <pdd/io/detail/text.hpp>
#include <pdd/io/svg_options.hpp>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <map>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace pdd {

/// Writes an SVG picture of a PSLG, atomically: y axis up (flipped to SVG's down), scaled to
/// options.width_px; segments coloured by marker, vertices as dots, holes as red crosses,
/// region points as blue dots.
/// \throws pdd::error naming the path for a segment with a missing vertex or a failed write.
/// Complexity: O(n log n). Thread-safety: reentrant.
inline void write_svg(const std::filesystem::path& path, const pslg& g,
                      const svg_options& options = {}) {
  detail::check_svg_pslg(g, path);
  write_file_atomically(path, [&](std::ostream& os) {
    detail::text_sink out(os);
    detail::svg_canvas c(out, detail::pslg_box(g), options);
    c.open("pdd PSLG: " + std::to_string(g.vertices.size()) + " vertices, " +
           std::to_string(g.segments.size()) + " segments, " + std::to_string(g.holes.size()) +
           " holes");
    detail::draw_pslg(c, g, options);
    c.close();
    out.flush();
  });
}

/// Writes an SVG picture of a mesh of any size, atomically: each subdomain (triangle marker)
/// filled in its own colour, the separators between subdomains in black, the boundary
/// segments coloured by marker, and the triangles (thin edges) when there are at most
/// options.max_triangles of them. A larger mesh, or any mesh given options.window, gets a
/// zoomed inset below the picture showing the triangles of the window (automatic for a large
/// mesh: about options.inset_triangles triangles on the separator nearest the centre), marked
/// by a red frame on the picture. options.legend adds the triangle, vertex and subdomain
/// counts and the smallest angle; options.shade_by_area shades the triangles by log(area)
/// (darkest smallest) and names the area range in the legend.
/// \throws pdd::error naming the path for an inconsistent mesh, an empty window or a failed
///   write.
/// Complexity: O(t log t). Thread-safety: reentrant.
inline void write_svg(const std::filesystem::path& path, const triangle_mesh& mesh,
                      const svg_options& options = {}) {
  detail::check_mesh_for_writing(mesh, path);
  if (options.window &&
      !(options.window->x0 < options.window->x1 && options.window->y0 < options.window->y1))
    throw error("cannot write '" + path.string() + "': the window needs x0 < x1 and y0 < y1");
  write_file_atomically(path, [&](std::ostream& os) {
    detail::text_sink out(os);
    detail::svg_box box;
    for (const point& p : mesh.vertices)
      box.add(p);
    const bool large = mesh.triangles.size() > options.max_triangles;
    const detail::marked_edges edges = detail::classify_edges(mesh);
    std::optional<svg_window> w = options.window;
    if (!w && large) w = detail::automatic_window(mesh, edges, box, options);
    detail::svg_canvas c(out, box, options);
    std::optional<detail::svg_canvas> inset;
    if (w) inset.emplace(out, detail::svg_box{w->x0, w->y0, w->x1, w->y1}, options);
    c.open("pdd mesh: " + std::to_string(mesh.vertices.size()) + " vertices, " +
               std::to_string(mesh.triangles.size()) + " triangles",
           inset ? inset->height() : 0.0);
    detail::draw_mesh(c, mesh, options);
    if (!large)
      c.segments(detail::separator_segments(mesh, edges), "#000000", options.segment_stroke_px);
    if (w) detail::draw_inset(out, c, *inset, mesh, edges, *w, options);
    if (options.legend) {
      std::vector<std::string> lines = detail::legend_lines(mesh);
      if (options.shade_by_area && !large) lines.push_back(detail::shading_legend(mesh));
      detail::legend_box(out, options.margin_px + 4, options.margin_px + 4, lines);
    }
    c.close();
    out.flush();
  });
}

/// Writes an SVG picture of a mesh with its PSLG drawn on top (segments, holes, regions).
/// \throws pdd::error as the other overloads.
inline void write_svg(const std::filesystem::path& path, const triangle_mesh& mesh,
                      const pslg& overlay, const svg_options& options = {}) {
  detail::check_mesh_for_writing(mesh, path);
  detail::check_svg_pslg(overlay, path);
  write_file_atomically(path, [&](std::ostream& os) {
    detail::text_sink out(os);
    detail::svg_box box = detail::pslg_box(overlay);
    for (const point& p : mesh.vertices)
      box.add(p);
    detail::svg_canvas c(out, box, options);
    c.open("pdd mesh: " + std::to_string(mesh.vertices.size()) + " vertices, " +
           std::to_string(mesh.triangles.size()) + " triangles, with its PSLG");
    detail::draw_mesh(c, mesh, options);
    svg_options thin = options;
    thin.vertex_radius_px = 0.0;
    detail::draw_pslg(c, overlay, thin);
    c.close();
    out.flush();
  });
}

/// Writes an SVG picture of a decomposition (dissertation ch. 3-4), atomically: each subdomain
/// filled with its own colour (holes left empty, even-odd rule), external edges and inner
/// constraint segments coloured by their boundary marker and interface edges in black, each
/// interface edge drawn once.
/// \throws pdd::error naming the path when a loop refers to a missing vertex or its tags do
///   not match it, or when writing fails.
/// Complexity: linear in the loop sizes. Thread-safety: reentrant.
inline void write_svg(const std::filesystem::path& path, const decomposition& d,
                      const svg_options& options = {}) {
  detail::check_decomposition(d, path);
  write_file_atomically(path, [&](std::ostream& os) {
    detail::text_sink out(os);
    detail::svg_box box;
    for (const point& p : d.vertices)
      box.add(p);
    detail::svg_canvas c(out, box, options);
    c.open("pdd decomposition: " + std::to_string(d.subdomains.size()) + " subdomains, " +
           std::to_string(d.interfaces.size()) + " interfaces");
    for (std::size_t s = 0; s < d.subdomains.size(); ++s) {
      c.begin_path("fill=\"" + detail::fill_colour(s) + "\" fill-rule=\"evenodd\" stroke=\"none\"");
      for (const auto& loop : d.subdomains[s].loops) {
        if (loop.size() < 3) continue;
        c.move_to(d.vertices[loop[0]]);
        for (std::size_t i = 1; i < loop.size(); ++i)
          c.line_to(d.vertices[loop[i]]);
        out.put('Z');
      }
      c.end_path();
    }
    detail::segments_by_marker external;
    std::vector<std::pair<point, point>> interfaces;
    for (std::size_t s = 0; s < d.subdomains.size(); ++s) {
      const subdomain& sd = d.subdomains[s];
      for (std::size_t l = 0; l < sd.loops.size(); ++l)
        for (std::size_t i = 0; i < sd.loops[l].size(); ++i) {
          const edge_tag& t = sd.tags[l][i];
          const point a = d.vertices[sd.loops[l][i]];
          const point b = d.vertices[sd.loops[l][(i + 1) % sd.loops[l].size()]];
          if (t.type == edge_tag::kind::external)
            external[t.marker].emplace_back(a, b);
          else if (t.neighbour == no_index || s < t.neighbour)
            interfaces.emplace_back(a, b);
        }
      for (const inner_constraint& ic : sd.inner)
        if (ic.segment != no_index && ic.a < d.vertices.size() && ic.b < d.vertices.size())
          external[ic.marker].emplace_back(d.vertices[ic.a], d.vertices[ic.b]);
    }
    detail::draw_marked_segments(c, external, options.segment_stroke_px);
    c.segments(interfaces, "#000000", options.segment_stroke_px);
    c.close();
    out.flush();
  });
}

} // namespace pdd
