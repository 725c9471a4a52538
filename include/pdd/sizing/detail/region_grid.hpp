/// \file region_grid.hpp
/// The geometry of pdd::sizing_range over a region: which nodes of an evaluation grid lie in
/// the closed region, and the points of the region's boundary in each cell. Declared here and
/// compiled into libpdd (src/compiled_sizing.cpp), so that the light headers that bound a field
/// (any_sizing.hpp, options.hpp) do not pull in CGAL's kernel; a header-only build
/// (PDD_HEADER_ONLY) includes the definition.
#pragma once

#include <pdd/core/bbox.hpp>
#include <pdd/core/point.hpp>
#include <pdd/sizing/sizing_region.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

#ifdef PDD_HEADER_ONLY
#define PDD_REGION_GRID_INLINE inline
#else
#define PDD_REGION_GRID_INLINE
#endif

namespace pdd::detail {

/// Node (i, j) of an nx x ny cell grid over box b (0 cells along a flat side: its one node);
/// the box rule (sample_field) and the region rule both take their nodes from here.
inline point grid_node(const pdd::bbox& b, std::size_t nx, std::size_t ny, std::size_t i,
                       std::size_t j) {
  return {
      nx ? b.xmin + (b.xmax - b.xmin) * static_cast<double>(i) / static_cast<double>(nx) : b.xmin,
      ny ? b.ymin + (b.ymax - b.ymin) * static_cast<double>(j) / static_cast<double>(ny) : b.ymin};
}

/// An nx x ny cell grid over a region's box: the nodes in the closed region, and per cell the
/// points of the region's boundary that lie in it (its corners inside the region, its boundary
/// edges' crossings of the grid lines), so that every cell that meets the region has at least
/// one sample of it.
struct region_grid {
  pdd::bbox box;              ///< the region's bounding box, which the grid spans
  std::size_t nx = 0, ny = 0; ///< cells along x and y (>= 1)
  /// Per node, row-major ((nx + 1) x (ny + 1), y rows): 1 when the node lies in the closed
  /// region (exact orientation tests against the region's triangles).
  std::vector<std::uint8_t> inside;
  std::vector<point> boundary; ///< boundary samples (edge ends and grid-line crossings)
  /// Per cell (nx x ny, row-major), its boundary samples: ids into `boundary` from
  /// cell_samples[cell_first[c]] to cell_samples[cell_first[c + 1]] (exclusive).
  std::vector<std::size_t> cell_first;
  std::vector<std::size_t> cell_samples; ///< see cell_first
  /// Node (i, j) of the grid.
  point node(std::size_t i, std::size_t j) const { return grid_node(box, nx, ny, i, j); }
  /// True when node (i, j) lies in the closed region.
  bool node_inside(std::size_t i, std::size_t j) const { return inside[j * (nx + 1) + i] != 0; }
};

/// The region grid of r with nx x ny cells over r.box().
/// \pre r is not empty and its box has a positive width and height; nx, ny >= 1.
/// Complexity O(T (rows + log T) + nodes inside + boundary crossings), T the triangles.
PDD_REGION_GRID_INLINE region_grid layout_region_grid(const sizing_region& r, std::size_t nx,
                                                      std::size_t ny);

} // namespace pdd::detail

#ifdef PDD_HEADER_ONLY
#include <pdd/sizing/detail/region_grid_impl.hpp>
#endif
