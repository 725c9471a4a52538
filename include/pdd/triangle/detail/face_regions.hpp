/// \file face_regions.hpp
/// Implementation of pdd::triangle::triangulate for switches A and a alone on a domain that is
/// not one of closed loops (Triangle's rule: internal segments separate faces): one run with
/// the regional area bounds as a sizing field, and the attribute of every triangle from the
/// face it lies in.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/generate.hpp>
#include <pdd/geometry/domain_faces.hpp>
#include <pdd/sizing/regional.hpp>
#include <pdd/triangle/detail/mesh_tables.hpp>
#include <pdd/triangle/switches.hpp>
#include <pdd/triangle/triangulation.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <unordered_set>
#include <utility>
#include <vector>

namespace pdd::triangle::detail {

/// The face (domain_faces' id, no_index outside the domain) of every triangle of a mesh of
/// `faces`' domain: the triangles joined across edges that lie on no input segment (m.segments)
/// are one face, located once by its first triangle's centroid. Complexity O(triangles) plus
/// one point location per face.
inline std::vector<index_t> triangle_faces(const domain_faces& faces, const triangle_mesh& m) {
  const auto key = [](index_t a, index_t b) {
    return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
  };
  std::unordered_set<std::uint64_t> on_segment;
  for (const mesh_edge& e : m.segments)
    on_segment.insert(key(e.a, e.b));
  const auto nb = neighbors(m);
  std::vector<index_t> out(m.triangles.size(), no_index);
  std::vector<char> seen(m.triangles.size(), 0);
  std::vector<std::size_t> stack;
  for (std::size_t seed = 0; seed < m.triangles.size(); ++seed) {
    if (seen[seed]) continue;
    const auto& t = m.triangles[seed];
    const point a = m.vertices[t[0]], b = m.vertices[t[1]], c = m.vertices[t[2]];
    const face_location at = faces.locate({(a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0});
    seen[seed] = 1;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const std::size_t u = stack.back();
      stack.pop_back();
      out[u] = at.face;
      for (int i = 0; i < 3; ++i) {
        const long long n = nb[u][static_cast<std::size_t>(i)];
        const auto& tu = m.triangles[u];
        if (n < 0 || seen[static_cast<std::size_t>(n)] ||
            on_segment.count(key(tu[(i + 1) % 3], tu[(i + 2) % 3])))
          continue;
        seen[static_cast<std::size_t>(n)] = 1;
        stack.push_back(static_cast<std::size_t>(n));
      }
    }
  }
  return out;
}

/// The regional attribute of every triangle: that of the last region point in its face (as
/// Triangle, which floods the regions in order), 0 in a face without one.
/// \throws pdd::geometry_error naming a region point on a segment or outside the domain.
inline std::vector<double> face_attributes(const pslg& domain, const triangle_mesh& m) {
  const domain_faces faces(domain);
  std::vector<double> of_face(faces.face_count(), 0.0);
  for (std::size_t r = 0; r < domain.regions.size(); ++r)
    of_face[pdd::detail::region_face(domain, faces, r)] = domain.regions[r].attribute;
  std::vector<double> out(m.triangles.size(), 0.0);
  const std::vector<index_t> face = triangle_faces(faces, m);
  for (std::size_t t = 0; t < out.size(); ++t)
    if (face[t] != no_index) out[t] = of_face[face[t]];
  return out;
}

/// Switches A and a alone on a domain that is not one of closed loops: one pdd::generate run
/// (the pipeline meshes it whole), with a alone the regions' area bounds as a sizing field
/// (pdd::regional_sizing: in each face the smallest bound of its region points, the uniform
/// bound elsewhere), with A every triangle's attribute from its face (face_attributes).
inline void mesh_face_regions(pslg domain, const switches& sw, generate_options gopt,
                              triangulation& out) {
  domain.rule = domain_rule::triangle;
  if (sw.regional_areas) {
    regional_sizing field(domain);
    if (field.bounded_regions() > 0) gopt.sizing = std::move(field);
  }
  generate_result r = generate(domain, gopt);
  out.mesh = std::move(r.mesh);
  out.runs.push_back(std::move(r.statistics));
  if (sw.regional_attributes) out.triangle_attributes = face_attributes(domain, out.mesh);
}

} // namespace pdd::triangle::detail
