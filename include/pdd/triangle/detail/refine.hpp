/// \file refine.hpp
/// Implementation of pdd::triangle::refine (Triangle's -r): the previous mesh as a PSLG (its
/// vertices, its segments and boundary edges, a hole point in every face it does not cover),
/// its .area bounds as a sizing field, its triangle attributes carried to the new triangles.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/errors.hpp>
#include <pdd/generate.hpp>
#include <pdd/geometry/domain_faces.hpp>
#include <pdd/io/previous_mesh.hpp>
#include <pdd/sizing/background_mesh.hpp>
#include <pdd/triangle/detail/conforming.hpp>
#include <pdd/triangle/detail/constrained_delaunay.hpp>
#include <pdd/triangle/detail/mesh_tables.hpp>
#include <pdd/triangle/detail/regions.hpp>
#include <pdd/triangle/switches.hpp>
#include <pdd/triangle/triangulation.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace pdd::triangle::detail {

inline point centroid(const std::vector<point>& v, const std::array<index_t, 3>& t) {
  return {(v[t[0]].x + v[t[1]].x + v[t[2]].x) / 3.0, (v[t[0]].y + v[t[1]].y + v[t[2]].y) / 3.0};
}

/// Every edge of `triangles` with the number of triangles it bounds, keyed by its two ends.
inline std::unordered_map<std::uint64_t, int>
edge_uses(const std::vector<std::array<index_t, 3>>& triangles) {
  std::unordered_map<std::uint64_t, int> uses;
  for (const auto& t : triangles)
    for (int i = 0; i < 3; ++i) {
      ++uses[edge_key(t[i], t[(i + 1) % 3])];
    }
  return uses;
}

/// Checks the previous mesh's tables (ids in range, counts). \throws pdd::geometry_error.
inline void check_previous(const previous_mesh& m) {
  const std::size_t n = m.input.vertices.size(), nt = m.triangles.size();
  if (nt == 0) throw geometry_error("-r: the previous mesh has no triangles");
  for (std::size_t t = 0; t < nt; ++t)
    for (const index_t v : m.triangles[t])
      if (v >= n)
        throw geometry_error("-r: triangle " + std::to_string(t) + " refers to vertex " +
                             std::to_string(v) + " of " + std::to_string(n));
  const auto per_triangle = [&](std::size_t k, const char* what) {
    if (k != 0 && k != nt)
      throw geometry_error(std::string("-r: ") + std::to_string(k) + " " + what + " for " +
                           std::to_string(nt) + " triangles");
  };
  per_triangle(m.triangle_attributes.size(), "triangle attributes");
  per_triangle(m.triangle_areas.size(), "triangle area bounds");
}

/// The previous mesh as a PSLG by Triangle's rule: its vertices and segments, every boundary
/// edge (an edge of one triangle) a segment of marker 1 unless it is one already, and a hole
/// point in every face of that arrangement that no previous triangle covers (a triangle of the
/// face's constrained Delaunay triangulation, its centroid: inside the face).
/// \throws pdd::geometry_error as pdd::validate.
inline pslg previous_domain(const previous_mesh& m) {
  pslg g = m.input;
  g.rule = domain_rule::triangle;
  g.holes.clear();
  g.regions.clear();
  std::unordered_map<std::uint64_t, int> uses = edge_uses(m.triangles);
  for (const segment& s : g.segments)
    uses.erase(edge_key(s.a, s.b));
  for (const auto& [key, count] : uses)
    if (count == 1) g.add_segment(static_cast<index_t>(key >> 32), static_cast<index_t>(key), 1);
  std::sort(g.segments.begin() + static_cast<std::ptrdiff_t>(m.input.segments.size()),
            g.segments.end(), [](const segment& a, const segment& b) {
              return std::pair{a.a, a.b} < std::pair{b.a, b.b};
            });
  const domain_faces faces(g);
  std::vector<char> covered(faces.face_count(), 0), holed(faces.face_count(), 0);
  for (const auto& t : m.triangles) {
    const face_location at = faces.locate(centroid(g.vertices, t));
    if (at.where == face_location::kind::inside) covered[at.face] = 1;
  }
  for (const domain_triangle& t : faces.triangles())
    if (!covered[t.face] && !holed[t.face]) {
      holed[t.face] = 1;
      g.holes.push_back(centroid(g.vertices, t.vertices));
    }
  return g;
}

/// The previous triangulation as a PSLG by Triangle's rule: its vertices (with their markers and
/// attributes) and every edge of its triangles a segment, so that each triangle is a face.
inline pslg previous_triangulation(const previous_mesh& m) {
  pslg all = m.input;
  all.segments.clear();
  all.holes.clear();
  all.regions.clear();
  all.rule = domain_rule::triangle;
  for (const auto& [key, count] : edge_uses(m.triangles))
    all.add_segment(static_cast<index_t>(key >> 32), static_cast<index_t>(key));
  return all;
}

/// The attribute of the previous triangle that holds each triangle of `mesh` (its centroid
/// located in the previous triangulation; 0 outside it).
inline std::vector<double> carried_attributes(const previous_mesh& m, const triangle_mesh& mesh) {
  const pslg all = previous_triangulation(m);
  const domain_faces faces(all); // every previous triangle is a face
  std::vector<double> of_face(faces.face_count(), 0.0);
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const face_location at = faces.locate(centroid(all.vertices, m.triangles[t]));
    if (at.where == face_location::kind::inside) of_face[at.face] = m.triangle_attributes[t];
  }
  std::vector<double> out(mesh.triangles.size(), 0.0);
  for (std::size_t t = 0; t < out.size(); ++t) {
    const face_location at = faces.locate(centroid(mesh.vertices, mesh.triangles[t]));
    if (at.where == face_location::kind::inside) out[t] = of_face[at.face];
  }
  return out;
}

/// Triangle's -r on `m` with switches sw (see pdd::triangle::refine).
inline triangulation refine_previous(const previous_mesh& m, const switches& sw,
                                     const triangulate_options& o) {
  check_previous(m);
  const pslg g = previous_domain(m);
  triangulation out;
  any_sizing sizing;
  if (sw.regional_areas && !m.triangle_areas.empty())
    sizing = background_mesh_sizing(m.input.vertices, m.triangles, m.triangle_areas,
                                    background_mesh_sizing::interpolation::per_triangle);
  if (conforming_path(sw)) {
    switches one = sw;
    one.regional_attributes = false; // carried from the previous triangles below
    out = conforming_mesh(g, one, sizing);
  } else if (!sw.quality) {
    out = constrained_delaunay(g, switches{});
  } else {
    generate_options gopt = options_for(sw, o);
    gopt.sizing = sizing;
    generate_result r = generate(g, gopt);
    out.mesh = std::move(r.mesh);
    out.runs.push_back(std::move(r.statistics));
    input_vertices_first(out.mesh, g);
  }
  if (!m.triangle_attributes.empty()) out.triangle_attributes = carried_attributes(m, out.mesh);
  return out;
}

} // namespace pdd::triangle::detail
