/// \file triangulate.hpp
/// pdd::triangle::triangulate: Triangle's `triangulate(switches, in, out)` on a pdd::pslg,
/// with pdd's decoupled pipeline (pdd::generate) doing the meshing. The module sits beside
/// pipeline/generate (it includes them); pdd-triangle and the Python `pdd.triangulate` use it.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/generate.hpp>
#include <pdd/geometry/loops.hpp>
#include <pdd/geometry/validate.hpp>
#include <pdd/mesh/region_attributes.hpp>
#include <pdd/triangle/detail/components.hpp>
#include <pdd/triangle/detail/face_regions.hpp>
#include <pdd/triangle/detail/mesh_tables.hpp>
#include <pdd/triangle/detail/regions.hpp>
#include <pdd/triangle/switches.hpp>
#include <pdd/triangle/triangulation.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <limits>
#include <vector>

namespace pdd::triangle {

/// Meshes `domain` as `triangle -<sw>` would mesh it, with pdd's pipeline.
///
/// Supported switches (pdd::triangle::parse_switches refuses the others): p (required: pdd
/// meshes the domain enclosed by segment loops), q[angle], a[area], a alone (the regions'
/// area bounds), A (regional attributes), O (the hole points are dropped: the holes are then
/// meshed, internal boundaries, as in Triangle), j (drop unused vertices), n (the
/// neighbour table). Q, V, N, E, P, B, I, z and r concern files and printing: the caller
/// (pdd-triangle, the Python module) honours them.
///
/// The domain is Triangle's (pdd::validate): every face of the segments' arrangement not
/// reachable from infinity or from a hole point without crossing a segment; internal and
/// dangling segments are mesh edges and isolated vertices inside the domain mesh vertices.
/// Differences from Triangle: without q the minimum angle is 0 but pdd's kernel still splits
/// segments that a vertex encroaches (its mesh is conforming, not Triangle's bare
/// constrained Delaunay triangulation). On a domain of closed loops (pdd::has_closed_loops) a
/// region is a connected component of the domain; when regional area bounds differ between
/// components, each component is meshed by its own pdd::generate run (the components share
/// no segment, so the union is conforming). On any other domain (meshed whole by the
/// pipeline) a region labels its face: one run with the regional bounds as a sizing field
/// (pdd::regional_sizing: the smallest bound among a face's region points, where Triangle
/// takes the last), attributes per face (detail::mesh_face_regions).
/// \throws switch_error without p; pdd::geometry_error for an invalid domain (after O);
///   everything pdd::generate throws.
/// Complexity: pdd::generate's, plus O(mesh) for the tables. Thread-safety: reentrant.
inline triangulation triangulate(pslg domain, const switches& sw,
                                 const triangulate_options& o = {}) {
  if (!sw.poly)
    throw switch_error("switch -p is required: pdd meshes the domain enclosed by the segments "
                       "(Triangle without -p triangulates the convex hull of the vertices)");
  if (sw.ignore_holes) domain.holes.clear();
  const bool closed_loops = has_closed_loops(domain); // validates
  const generate_options gopt = detail::options_for(sw, o);
  triangulation out;
  if (!domain.regions.empty() && (sw.regional_areas || sw.regional_attributes) && !closed_loops) {
    detail::mesh_face_regions(domain, sw, gopt, out);
  } else if (!domain.regions.empty() && (sw.regional_areas || sw.regional_attributes)) {
    detail::mesh_regions(domain, sw, gopt, out);
  } else {
    generate_result r = generate(domain, gopt);
    out.mesh = std::move(r.mesh);
    out.runs.push_back(std::move(r.statistics));
    if (sw.regional_attributes) out.triangle_attributes.assign(out.mesh.triangles.size(), 0.0);
  }
  detail::input_vertices_first(out.mesh, domain);
  if (sw.jettison) out.jettisoned_vertices = detail::jettison_unused_vertices(out.mesh);
  if (sw.neighbors) out.neighbors = triangle_neighbors(out.mesh);
  return out;
}

} // namespace pdd::triangle
