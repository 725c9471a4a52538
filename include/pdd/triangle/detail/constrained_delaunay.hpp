/// \file constrained_delaunay.hpp
/// Implementation of pdd::triangle::triangulate with p and no refinement switch (q, a): the
/// constrained Delaunay triangulation of the PSLG, as Triangle's bare `-p` makes it, with no
/// Steiner point.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/geometry/domain_faces.hpp>
#include <pdd/mesh/region_attributes.hpp>
#include <pdd/triangle/detail/mesh_tables.hpp>
#include <pdd/triangle/switches.hpp>
#include <pdd/triangle/triangulation.hpp>

#include <algorithm>
#include <cstdint>
#include <unordered_set>
#include <utility>
#include <vector>

namespace pdd::triangle::detail {

/// The input segments that are edges of the triangles `m` holds (a segment in a hole or
/// outside the domain is none), with their markers, in input order.
inline std::vector<mesh_edge> segments_in_mesh(const pslg& g, const triangle_mesh& m) {
  std::unordered_set<std::uint64_t> edges;
  edges.reserve(3 * m.triangles.size());
  for (const auto& t : m.triangles)
    for (int i = 0; i < 3; ++i)
      edges.insert(edge_key(t[i], t[(i + 1) % 3]));
  std::vector<mesh_edge> out;
  for (const segment& s : g.segments)
    if (edges.contains(edge_key(s.a, s.b))) out.push_back({s.a, s.b, s.marker});
  return out;
}

/// Switch p without q or a: the constrained Delaunay triangulation of `domain` (CGAL, exact
/// predicates; the one pdd::validate builds) restricted to the domain by Triangle's rule, every
/// vertex the input's, in input order (those outside the domain kept, as Triangle keeps them;
/// j drops them); triangle markers 0; with A the regional attributes (pdd::region_attributes).
/// \throws pdd::geometry_error as pdd::validate (crossing segments, equal vertices, ...).
/// Complexity O(n log n) expected.
inline triangulation constrained_delaunay(pslg domain, const switches& sw) {
  domain.rule = domain_rule::triangle;
  const domain_faces faces(domain, domain_faces::validate_first{});
  triangulation out;
  triangle_mesh& m = out.mesh;
  m.vertices = domain.vertices;
  m.vertex_markers = domain.vertex_markers;
  m.vertex_markers.resize(m.vertices.size(), 0);
  for (const domain_triangle& t : faces.triangles())
    m.triangles.push_back(t.vertices);
  m.triangle_markers.assign(m.triangles.size(), 0);
  m.segments = segments_in_mesh(domain, m);
  if (sw.regional_attributes) out.triangle_attributes = region_attributes(domain, m);
  return out;
}

} // namespace pdd::triangle::detail
