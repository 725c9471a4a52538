/// \file svg_options.hpp
/// pdd::svg_options: how pdd::write_svg draws its pictures.
#pragma once

#include <cstddef>

namespace pdd {

/// Options of pdd::write_svg.
struct svg_options {
  double width_px = 1000.0;           ///< picture width; the height follows the aspect ratio
  double margin_px = 10.0;            ///< blank border around the drawing
  std::size_t max_triangles = 200000; ///< larger meshes: only the boundary segments are drawn
  double mesh_stroke_px = 0.3;        ///< mesh edges
  double segment_stroke_px = 1.5;     ///< input segments, boundary and interface edges
  double vertex_radius_px = 1.5;      ///< PSLG vertices (0: not drawn)
  double hole_size_px = 4.0;          ///< half size of the hole crosses
  int precision = 2;                  ///< digits after the point in pixel coordinates
};

} // namespace pdd
