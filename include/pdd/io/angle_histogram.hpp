/// \file angle_histogram.hpp
/// pdd::write_angle_histogram_svg: a bar chart of every triangle angle of a mesh (1-degree
/// bins), with the smallest and largest angle marked.
#pragma once

#include <pdd/core/triangle_mesh.hpp>
#include <pdd/io/atomic_file.hpp>
#include <pdd/io/detail/mesh.hpp>
#include <pdd/io/detail/mesh_picture.hpp>
#include <pdd/io/detail/text.hpp>

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <ostream>
#include <string>

namespace pdd {

namespace detail {
/// A vertical line at `deg` with a label.
inline void histogram_marker(text_sink& out, double x, double top, double bottom,
                             const std::string& label, const char* colour) {
  out.put("<line x1=\"").fixed(x, 2).put("\" y1=\"").fixed(top, 2).put("\" x2=\"").fixed(x, 2);
  out.put("\" y2=\"").fixed(bottom, 2).put("\" stroke=\"").put(colour);
  out.put("\" stroke-width=\"1.5\" stroke-dasharray=\"4 3\"/>\n<text x=\"").fixed(x + 4, 2);
  out.put("\" y=\"").fixed(top + 14, 2).put("\" fill=\"").put(colour).put("\">").put(label);
  out.put("</text>\n");
}
} // namespace detail

/// Writes an SVG bar chart of the angles of every triangle of `mesh` (3 per triangle, 1-degree
/// bins from 0 to 180), atomically: bar heights relative to the
/// fullest bin, x axis labelled every 30 degrees, dashed lines at the smallest and largest
/// angle, a title with the triangle count.
/// \throws pdd::error naming the path for an inconsistent mesh or a failed write.
/// Complexity O(t). Thread-safety: reentrant.
inline void write_angle_histogram_svg(const std::filesystem::path& path,
                                      const triangle_mesh& mesh) {
  detail::check_mesh_for_writing(mesh, path);
  const detail::angle_summary q = detail::summarize_angles(mesh);
  constexpr double left = 60, top = 40, bin = 4, height = 240; // 180 bins x 4 px
  const double bottom = top + height, right = left + 180 * bin;
  const std::size_t fullest =
      std::max<std::size_t>(1, *std::max_element(q.bins.begin(), q.bins.end()));
  write_file_atomically(path, [&](std::ostream& os) {
    detail::text_sink out(os);
    out.put("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
            "width=\"820\" height=\"330\" viewBox=\"0 0 820 330\" font-family=\"sans-serif\" "
            "font-size=\"13\">\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n");
    out.put("<text x=\"").fixed(left, 0).put("\" y=\"24\" font-size=\"15\">Angles of ");
    out.integer(mesh.triangles.size()).put(" triangles (1-degree bins; fullest bin ");
    out.integer(fullest).put(")</text>\n<path fill=\"#1f77b4\" d=\"");
    for (std::size_t b = 0; b < 180; ++b) {
      if (q.bins[b] == 0) continue;
      const double h = height * static_cast<double>(q.bins[b]) / static_cast<double>(fullest);
      out.put('M').fixed(left + bin * static_cast<double>(b), 2).put(' ').fixed(bottom, 2);
      out.put("h").fixed(bin - 0.5, 2).put("v-").fixed(h, 2).put("h-").fixed(bin - 0.5, 2).put('Z');
    }
    out.put("\"/>\n<path stroke=\"#000000\" fill=\"none\" d=\"M").fixed(left, 0).put(' ');
    out.fixed(top, 0).put('V').fixed(bottom, 0).put('H').fixed(right, 0).put("\"/>\n");
    for (int deg = 0; deg <= 180; deg += 30) {
      const double x = left + bin * deg;
      out.put("<text x=\"").fixed(x, 1).put("\" y=\"").fixed(bottom + 18, 1);
      out.put("\" text-anchor=\"middle\">").integer(deg).put("</text>\n");
    }
    out.put("<text x=\"").fixed((left + right) / 2, 1).put("\" y=\"").fixed(bottom + 38, 1);
    out.put("\" text-anchor=\"middle\">angle (degrees)</text>\n");
    std::string lo = "smallest ", hi = "largest ";
    detail::append_fixed(lo, q.min_deg, 2);
    detail::append_fixed(hi, q.max_deg, 2);
    detail::histogram_marker(out, left + bin * q.min_deg, top, bottom, lo, "#d62728");
    detail::histogram_marker(out, left + bin * q.max_deg, top, bottom, hi, "#d62728");
    out.put("</svg>\n");
    out.flush();
  });
}

} // namespace pdd
