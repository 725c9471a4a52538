/// \file mesher.hpp
/// pdd::native::mesher: a DelaunayMesher written for pdd (no CGAL triangulation): a
/// triangle-array constrained Delaunay triangulation with Ruppert's refinement. This header
/// declares it; its definition is in kernels/native/mesher_templates.hpp, which a program
/// includes to mesh with a SizingField of its own. libpdd holds it for pdd::any_sizing and
/// pdd::uniform_sizing; in a header-only build (PDD_HEADER_ONLY) this header includes it.
#pragma once

#include <pdd/concepts/delaunay_mesher.hpp>
#include <pdd/concepts/sizing_field.hpp>
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/pslg.hpp>

namespace pdd::native {

/// Meshes one planar straight-line domain by Delaunay refinement on flat arrays (Ruppert 1995,
/// Shewchuk 1997/2002) — dissertation ch. 1.1 and 6.1, the sequential mesher every subdomain
/// is handed to. Models pdd::DelaunayMesher with the semantics of pdd::cgal::mesher.
///
/// Algorithm: the input vertices are inserted in Hilbert order (CGAL's spatial_sort) into a
/// bounding triangle by Bowyer-Watson cavities located by a visibility walk from the last
/// insertion; segments are recovered by flips and the constrained Delaunay property restored
/// by Lawson's flips; the domain is marked by flood fill (odd nesting of segment loops, less
/// hole regions); then refinement (detail/refine.hpp): encroached subsegments are split at
/// their midpoints (on concentric shells next to an input vertex), bad triangles get their
/// off-centres or circumcentres (kernels/detail/off_centre.hpp) from a bucketed queue, and a
/// point that encroaches a subsegment is not inserted: the subsegment is split instead. A
/// subsegment is encroached only by vertices on a domain side of it. Every geometric decision uses
/// Epick's exact predicates (orientation, in-circle, angle); no epsilon decides topology.
///
/// Small input angles: Ruppert's concentric shells and Shewchuk's rule (a triangle that is bad
/// only in shape and whose shortest edge joins the two segments of an input angle below 60 deg
/// on one shell is left). Shielded domains (pdd::shield) have none, and every triangle meets
/// the bound there; with unshielded small angles a few triangles at them may not.
///
/// Output: as pdd::cgal::mesher (input vertices first, bit for bit, with their markers; then
/// Steiner vertices in insertion order; in-domain triangles counter-clockwise, marker 0;
/// `segments` the mesh edges on input segments with their markers). Deterministic: the same
/// input gives bitwise the same result on every run and thread.
///
/// Memory: 32 bytes per triangle slot (corners, packed neighbours, flag bits, aligned so that
/// a slot is one cache line's half) and 24 per vertex (coordinates, a triangle reference, the
/// segment of a Steiner vertex), plus the bad-triangle queue; with an area bound the arrays
/// are reserved for the expected mesh once instead of growing by copies.
///
/// Thread-safety: the object is stateless; any number of `mesh` calls may run concurrently.
struct mesher {
  /// Meshes the domain of d. Complexity: O(n log n) expected in the output size n.
  /// \tparam S a SizingField (area bound at a point, sampled at triangle centroids).
  /// \pre criteria.min_angle_deg in [0, 60) (refinement is guaranteed to terminate for
  ///   <= 20.7 deg with input angles >= 60 deg); criteria.max_area > 0; sizing.area_at > 0.
  /// \throws meshing_error (subdomain -1) for unusable input (non-finite or coinciding
  ///   vertices, bad or crossing segments, a vertex inside a segment, marker count mismatch,
  ///   criteria out of range) or bounds finer than the floating-point resolution.
  template <SizingField S>
  mesher_result mesh(const pslg& d, const mesh_criteria& criteria, const S& sizing) const;
};

} // namespace pdd::native

static_assert(pdd::DelaunayMesher<pdd::native::mesher>);

#ifdef PDD_HEADER_ONLY
#include <pdd/kernels/native/mesher_templates.hpp>
#endif
