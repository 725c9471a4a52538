/// \file sizing_region.hpp
/// pdd::sizing_region: the closed region of the plane over which pdd::sizing_range bounds a
/// field (a domain or subdomain given by the triangles that cover it, holes and outside left out).
#pragma once

#include <pdd/core/bbox.hpp>
#include <pdd/core/index.hpp>
#include <pdd/core/point.hpp>

#include <algorithm>
#include <array>
#include <span>

namespace pdd {

/// A closed region given as triangles over a vertex array: the union of the triangles (e.g. a
/// domain's faces, pdd::domain_faces::triangles(), or pdd::triangulated_region). Views only:
/// the arrays must outlive it. The triangles must not overlap (a triangulation of the region);
/// their orientation does not matter.
struct sizing_region {
  std::span<const point> vertices;                   ///< the points the triangles index
  std::span<const std::array<index_t, 3>> triangles; ///< the region's triangles

  /// True when the region has no triangle.
  bool empty() const noexcept { return triangles.empty(); }
  /// The bounding box of the triangles' corners (empty box for an empty region).
  pdd::bbox box() const {
    pdd::bbox b;
    for (const auto& t : triangles)
      for (const index_t v : t) {
        const point& p = vertices[v];
        b = {std::min(b.xmin, p.x), std::min(b.ymin, p.y), std::max(b.xmax, p.x),
             std::max(b.ymax, p.y)};
      }
    return b;
  }
};

} // namespace pdd
