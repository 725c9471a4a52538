/// \file sizing_range.hpp
/// pdd::sizing_range: m(D) and M(D) of any SizingField over a region or a box (dissertation
/// 7.3-7.5).
#pragma once

#include <pdd/concepts/sizing_field.hpp>
#include <pdd/sizing/detail/sampled_range.hpp>
#include <pdd/sizing/detail/sampled_region_range.hpp>
#include <pdd/sizing/sizing_region.hpp>

#include <concepts>
#include <cstddef>

namespace pdd {

/// Grid resolution of pdd::sizing_range for fields without range().
struct sizing_range_options {
  /// Cells per side of the first evaluation grid (refined x4 up to 1024 when needed).
  std::size_t cells = 64;
  /// Mesh-scale resolution; 0 (the default): off. When > 0, a first 8 x 8 grid bounds the
  /// field below by lo, and the grid then has ceil(mesh_resolution * L / sqrt(lo)) cells a side
  /// (L the box's longer side), at least 8 and at most `cells`: cells no longer than
  /// sqrt(lo) / mesh_resolution. At 1 they are shorter than the edges of the smallest
  /// triangles the field asks for (a triangle of area >= lo/2 and angles >= 20.7 deg has no
  /// edge below sqrt(lo)), so the grid still resolves F at the scale of the mesh that F
  /// makes (the kernel itself sees F only at its triangles' points), while a box holding a
  /// few hundred triangles costs ~100-1000 evaluations instead of 4225. Algorithm 7.1 measures
  /// its leaves so (pdd::gradation_options); a field narrower than the mesh it asks for is
  /// as invisible to it as to the kernel, and a decoupling path it breaks is still caught by
  /// the kernel's run-time check of the interface pieces.
  double mesh_resolution = 0.0;
};

/// A field that forwards range() to other fields (any_sizing, min_sizing) takes the options
/// along as range(box, options).
template <class F>
concept RangeWithOptions = requires(const F& f, const bbox& b, const sizing_range_options& o) {
  { f.range(b, o) } -> std::convertible_to<sizing_bounds>;
};

/// A field that bounds itself over a region (any_sizing, min_sizing and the pipeline's derived
/// fields, which forward to the fields they hold) answers range(region, options).
template <class F>
concept RegionRangeWithOptions = requires(const F& f, const sizing_region& r,
                                          const sizing_range_options& o) {
  { f.range(r, o) } -> std::convertible_to<sizing_bounds>;
};

/// Bounds lo <= F(p) <= hi over the closed box `b`. The pipeline bounds fields over regions
/// (the overload below): a field need only be positive and finite on the domain, while over a
/// box it must be so in the holes and around the domain too.
///
/// A BoundedSizingField answers with its own f.range(b) (exact from nodes for background
/// meshes and grids, exact for uniform fields). Any other SizingField (a callable, an
/// expression) is evaluated on a grid of `o.cells` x `o.cells` cells over the box, and each
/// cell contributes lo = (smallest corner value) - 2 (Dxx + Dyy) / 8 and hi = (largest corner
/// value) + 2 (Dxx + Dyy) / 8, where Dxx and Dyy are the largest |second differences| of the
/// node values around the cell (its nodes and its 8 neighbours). Safety rule: (Dxx + Dyy) / 8
/// is the classical bound on how far a function with second derivatives h^2 |f_xx| <= Dxx,
/// h^2 |f_yy| <= Dyy dips below its bilinear interpolant in a cell; the factor 2 covers a
/// curvature up to twice what the surrounding nodes show. So lo is a true lower bound for
/// every linear, bilinear and quadratic field (exact second differences), and for every
/// smooth field whose curvature the grid resolves; it cannot see a feature narrower than a
/// cell (no sampling can): give such a field a range() (e.g. analytic_sizing with a range
/// function) or use a background mesh. When the margin leaves no positive lower bound the
/// grid is refined x4 (to 1024 cells per side at most). With o.mesh_resolution > 0 the first
/// grid may be coarser than o.cells (see sizing_range_options::mesh_resolution).
/// \tparam F a SizingField. \throws pdd::sizing_error for a value <= 0 or NaN at a node, or
/// no positive lower bound at 1024 cells. An empty box gives {inf, inf}.
/// Complexity: O(cells^2) evaluations for unbounded fields. Thread-safe when F is.
template <SizingField F>
sizing_bounds sizing_range(const F& f, const bbox& b, const sizing_range_options& o = {}) {
  if constexpr (RangeWithOptions<F>)
    return f.range(b, o);
  else if constexpr (BoundedSizingField<F>)
    return f.range(b);
  else
    return detail::sampled_range(f, b, o.cells, o.mesh_resolution);
}

/// Bounds lo <= F(p) <= hi over the closed region `r` (the customisation point of the graded
/// method's m(D) and M(D): the pipeline passes the domain or subdomain itself, so a field is
/// evaluated only where the mesh will be, never in a hole or outside the domain).
///
/// A field with range(region, options) answers it; a BoundedSizingField answers f.range over
/// the region's bounding box (its bound over the box bounds the region too; those fields are
/// positive everywhere by construction). Any other SizingField is evaluated on the grid rule of
/// the box overload over the region's box, with samples in the region only: the grid nodes
/// that lie in the closed region (exact orientation tests against its triangles) and, in every
/// cell the region's boundary crosses, the boundary's crossings of the cell's sides and the
/// boundary vertices in it. Each cell that meets the region contributes lo = (smallest sample)
/// - 2 (Dxx + Dyy) / 8 and hi = (largest sample) + 2 (Dxx + Dyy) / 8, Dxx and Dyy the largest
/// |second differences| along x and y around the cell among the nodes in the region; the grid
/// is refined x4 (to 1024 cells a side) while no positive lower bound results.
/// \tparam F a SizingField. \throws pdd::sizing_error naming a point of the region where the
/// value is <= 0 or NaN, or when no positive lower bound results at 1024 cells. An empty region
/// gives {inf, inf}. Complexity: O(cells^2 + T rows) for fields without a range (T the
/// region's triangles). Thread-safe when F is.
template <SizingField F>
sizing_bounds sizing_range(const F& f, const sizing_region& r, const sizing_range_options& o = {}) {
  if constexpr (RegionRangeWithOptions<F>)
    return f.range(r, o);
  else if constexpr (RangeWithOptions<F>)
    return f.range(r.box(), o);
  else if constexpr (BoundedSizingField<F>)
    return f.range(r.box());
  else
    return detail::sampled_region_range(f, r, o.cells, o.mesh_resolution);
}

} // namespace pdd
