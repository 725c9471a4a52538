/// \file svg_options.hpp
/// pdd::svg_options: how pdd::write_svg draws its pictures.
#pragma once

#include <cstddef>
#include <optional>

namespace pdd {

/// A window of the model plane, x0 < x1 and y0 < y1.
struct svg_window {
  /// \var x0
  /// Left edge, in model coordinates.
  /// \var y0
  /// Bottom edge, in model coordinates.
  /// \var x1
  /// Right edge, in model coordinates (> x0).
  /// \var y1
  /// Top edge, in model coordinates (> y0).
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
};

/// Options of pdd::write_svg.
struct svg_options {
  double width_px = 1000.0; ///< picture width; the height follows the aspect ratio
  double margin_px = 10.0;  ///< blank border around the drawing
  /// Larger meshes are drawn as their subdomains (filled), separators and boundary segments,
  /// with a zoomed inset below that shows the triangles of a window.
  std::size_t max_triangles = 200000;
  /// The inset's window; none: automatic for large meshes (a square of about inset_triangles
  /// triangles on the separator nearest the centre). Given: the inset is drawn for any size.
  std::optional<svg_window> window;
  std::size_t inset_triangles = 3000; ///< triangles in the automatic window
  bool legend = true;                 ///< mesh pictures: triangles, subdomains, smallest angle
  double mesh_stroke_px = 0.3;        ///< mesh edges
  double segment_stroke_px = 1.5;     ///< input segments, boundary and interface edges
  double vertex_radius_px = 1.5;      ///< PSLG vertices (0: not drawn)
  double hole_size_px = 4.0;          ///< half size of the hole crosses
  int precision = 2;                  ///< digits after the point in pixel coordinates
  /// Mesh pictures drawn triangle by triangle: shade each triangle over its subdomain's fill
  /// by log(area), the smallest triangles darkest (area_shades steps from the mesh's smallest
  /// to its largest area; the legend gives the range): the grading of a graded mesh at a glance.
  bool shade_by_area = false;
  int area_shades = 8; ///< steps of the shading (>= 2)
};

} // namespace pdd
