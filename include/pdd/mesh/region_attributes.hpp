/// \file region_attributes.hpp
/// pdd::region_attributes: the regional attribute (Triangle's `-A`) of every triangle of a
/// mesh, from the face of the domain it lies in; pdd::triangle_faces: that face;
/// pdd::triangle_neighbors: the triangle across each edge.
#pragma once

#include <pdd/core/index.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_measures.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/geometry/domain_faces.hpp>
#include <pdd/sizing/regional.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace pdd {

/// The triangle across from vertex i of each triangle (Triangle's .neigh convention), -1 on
/// the mesh's boundary. Complexity O(triangles) expected. Thread-safety: reentrant.
inline std::vector<std::array<long long, 3>> triangle_neighbors(const triangle_mesh& m) {
  std::unordered_map<std::uint64_t, std::pair<index_t, int>> open;
  open.reserve(m.triangles.size() * 2);
  std::vector<std::array<long long, 3>> out(m.triangles.size(), {-1, -1, -1});
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      index_t a = m.triangles[t][(i + 1) % 3], b = m.triangles[t][(i + 2) % 3];
      if (a > b) std::swap(a, b);
      const std::uint64_t k = (std::uint64_t{a} << 32) | b;
      const auto [it, inserted] = open.try_emplace(k, static_cast<index_t>(t), i);
      if (inserted) continue;
      out[t][static_cast<std::size_t>(i)] = it->second.first;
      out[it->second.first][static_cast<std::size_t>(it->second.second)] =
          static_cast<long long>(t);
      open.erase(it);
    }
  return out;
}

/// The face (domain_faces' id, no_index outside the domain) of every triangle of a mesh of
/// `faces`' domain: the triangles joined across edges that lie on no input segment or
/// interface (m.segments) are one piece of one face, located once by its first triangle's
/// centroid. Complexity O(triangles) expected plus one point location per piece.
/// Thread-safety: reentrant.
inline std::vector<index_t> triangle_faces(const domain_faces& faces, const triangle_mesh& m) {
  const auto key = [](index_t a, index_t b) {
    return (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
  };
  std::unordered_set<std::uint64_t> on_segment;
  for (const mesh_edge& e : m.segments)
    on_segment.insert(key(e.a, e.b));
  const auto nb = triangle_neighbors(m);
  std::vector<index_t> out(m.triangles.size(), no_index);
  std::vector<char> seen(m.triangles.size(), 0);
  std::vector<std::size_t> stack;
  for (std::size_t seed = 0; seed < m.triangles.size(); ++seed) {
    if (seen[seed]) continue;
    const auto& t = m.triangles[seed];
    const face_location at = faces.locate(
        detail::triangle_centroid(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]));
    seen[seed] = 1;
    stack.assign(1, seed);
    while (!stack.empty()) {
      const std::size_t u = stack.back();
      stack.pop_back();
      out[u] = at.face;
      const auto& tu = m.triangles[u];
      for (int i = 0; i < 3; ++i) {
        const long long n = nb[u][static_cast<std::size_t>(i)];
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

/// The regional attribute of every triangle of a mesh of `domain` (Triangle's switch A): that
/// of the last region point in the triangle's face (as Triangle, which floods the regions in
/// order), 0 in a face without one. The faces follow domain.rule (pdd::domain_faces): on a
/// domain of closed loops a face is a connected component of the domain, under Triangle's rule
/// the pieces between segments (internal constraints separate faces).
/// \throws pdd::geometry_error naming a region point on a segment or outside the domain.
/// Complexity: that of domain_faces and triangle_faces. Thread-safety: reentrant.
inline std::vector<double> region_attributes(const pslg& domain, const triangle_mesh& m) {
  const domain_faces faces(domain);
  std::vector<double> of_face(faces.face_count(), 0.0);
  for (std::size_t r = 0; r < domain.regions.size(); ++r)
    of_face[detail::region_face(domain, faces, r)] = domain.regions[r].attribute;
  std::vector<double> out(m.triangles.size(), 0.0);
  const std::vector<index_t> face = triangle_faces(faces, m);
  for (std::size_t t = 0; t < out.size(); ++t)
    if (face[t] != no_index) out[t] = of_face[face[t]];
  return out;
}

} // namespace pdd
