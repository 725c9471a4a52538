/// \file delaunay_mesher.hpp
/// The DelaunayMesher concept.
///
/// A DelaunayMesher meshes one planar straight-line domain under quality criteria and a
/// sizing field, and reports which input segments it split.
///
/// Requirements: for `const M m`, `const pdd::pslg d`, `const pdd::mesh_criteria c` and any
/// SizingField `s`, `m.mesh(d, c, s)` returns a pdd::mesher_result. The concept is checked with
/// detail::sizing_field_archetype (the least a SizingField offers); models provide `mesh` as a
/// template over SizingField.
///
/// Domain: by d.rule (pdd::domain_rule): odd_nesting, the faces enclosed by an odd number of
/// the pslg's closed segment loops; triangle, every face not reachable from the unbounded face
/// without crossing a segment (Triangle's rule); either less any region reached from a hole
/// point without crossing a segment. Segments inside the domain (internal, dangling) are
/// constraints: unions of mesh edges; input vertices inside it are mesh vertices.
///
/// Semantics the decoupling proofs rely on (dissertation ch. 1.1, 6.1): the model is a
/// Delaunay refinement (Ruppert-type) mesher. It never moves or removes input vertices
/// (their coordinates are copied bit for bit), splits an input segment only when it is
/// encroached (a vertex inside its diametral circle), keeps the (constrained) Delaunay property,
/// and never creates an edge shorter than lfs_min when input angles are >= 60 deg. Every
/// triangle of the result meets the ratio bound and the area bound (criteria.max_area and
/// s.area_at at the centroid). `split_segments` lists, in increasing order, the indices of the
/// input segments that are not edges of the final mesh. Many instances may run concurrently on
/// different inputs.
///
/// Models: pdd::cgal::mesher (default).
#pragma once

#include <pdd/concepts/sizing_field.hpp>
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>

#include <concepts>
#include <vector>

namespace pdd {

/// What a DelaunayMesher returns.
struct mesher_result {
  /// The mesh; its first d.vertices.size() vertices are the input vertices in input order.
  triangle_mesh mesh;
  /// Indices of input segments that the mesher split (not edges of the final mesh).
  std::vector<index_t> split_segments;
};

namespace detail {
/// A SizingField with nothing but what the concept requires (Boost's archetype idiom): the
/// type DelaunayMesher is checked with, so that the concept does not depend on sizing/.
struct sizing_field_archetype {
  double area_at(const point&) const noexcept { return 1.0; }
};
static_assert(SizingField<sizing_field_archetype>);
} // namespace detail

template <class M>
concept DelaunayMesher = requires(const M& m, const pslg& d, const mesh_criteria& c,
                                  const detail::sizing_field_archetype& s) {
  { m.mesh(d, c, s) } -> std::same_as<mesher_result>;
};

} // namespace pdd
