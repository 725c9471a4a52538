/// \file mesher.hpp
/// pdd::cgal::mesher: the default DelaunayMesher, over CGAL's constrained Delaunay
/// triangulation and Mesh_2 Delaunay refinement. This header declares it; its definition
/// (CGAL's mesher behind it) is in kernels/cgal/mesher_templates.hpp, which a program includes
/// to mesh with a SizingField of its own. libpdd holds it for pdd::any_sizing and
/// pdd::uniform_sizing; in a header-only build (PDD_HEADER_ONLY) this header includes it.
#pragma once

#include <pdd/concepts/delaunay_mesher.hpp>
#include <pdd/concepts/sizing_field.hpp>
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/pslg.hpp>

namespace pdd::cgal {

/// Meshes one planar straight-line domain with CGAL 5.5's Constrained_Delaunay_triangulation_2
/// (Epick kernel) refined by the levels of Delaunay_mesher_2 (Ruppert-type refinement with
/// Shewchuk's cluster handling for small input angles), under a shape bound and an area bound
/// (criteria.max_area and a SizingField) — dissertation ch. 1.1 and 6.1, the sequential mesher
/// every subdomain is handed to. Models pdd::DelaunayMesher; see its semantics.
///
/// Differences from CGAL's Delaunay_mesher_2: the domain is marked before refinement (by
/// d.rule: odd nesting of segment loops or Triangle's rule, less hole regions, see
/// concepts/delaunay_mesher.hpp; internal and dangling constraints and isolated vertices are
/// kept as mesh edges and vertices; by Triangle's rule a segment with no domain face on either
/// side is left out, as Triangle does, detail::cgal_mesh::release_outside_segments), a segment
/// counts as encroached only by vertices on a side of it that lies in the domain (as in
/// Triangle), a bad face is left unrefined by the cluster rule for small input angles only when
/// the small angle lies in the domain (CGAL also did so at sharp corners of holes and notches,
/// detail/cluster_rule.hpp), a bad face is refined at its off-centre where that is nearer to
/// its shortest edge than its circumcentre (kernels/detail/off_centre.hpp, as Triangle does),
/// and the criteria are pdd::cgal::sizing_criteria.
///
/// Output: the input vertices first, in input order, with their coordinates and markers copied
/// bit for bit; then the Steiner vertices in the triangulation's insertion order (deterministic:
/// the same input gives bitwise the same output). A Steiner vertex on an input segment gets
/// the segment's marker, any other 0. Triangles are the in-domain faces, counter-clockwise,
/// marker 0; `segments` holds the mesh edges on input segments (sorted, a < b) with their
/// segment's marker.
///
/// Thread-safety: the object is stateless; any number of `mesh` calls may run concurrently.
struct mesher {
  /// Meshes the domain of d. Complexity: O(n log n) expected in the output size n.
  /// \tparam S a SizingField (area bound at a point, sampled at triangle centroids).
  /// \pre criteria.min_angle_deg in [0, 60) (refinement is guaranteed to terminate for
  ///   <= 20.7 deg with input angles >= 60 deg, and usually does up to about 33 deg);
  ///   criteria.max_area > 0; sizing.area_at > 0 everywhere.
  /// \throws meshing_error (subdomain -1) for unusable input (non-finite or coinciding
  ///   vertices, bad or crossing segments, a vertex inside a segment, marker count mismatch,
  ///   criteria out of range) or when CGAL fails.
  template <SizingField S>
  mesher_result mesh(const pslg& d, const mesh_criteria& criteria, const S& sizing) const;
};

} // namespace pdd::cgal

static_assert(pdd::DelaunayMesher<pdd::cgal::mesher>);

#ifdef PDD_HEADER_ONLY
#include <pdd/kernels/cgal/mesher_templates.hpp>
#endif
