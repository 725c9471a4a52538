/// \file apply_shields.hpp
/// pdd::add_shield_triangles: completes the kernel's mesh of a shielded domain D' with the
/// shielded triangles T_D (dissertation 8.1, Theorem 24).
#pragma once

#include <pdd/concepts/delaunay_mesher.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/errors.hpp>
#include <pdd/shielding/shield_triangle.hpp>

#include <algorithm>
#include <map>
#include <utility>
#include <vector>

namespace pdd {

/// Adds the shielded triangles `tris` to r, the kernel's result for the shielded domain
/// `input` (whose first vertices are the input vertices, as every DelaunayMesher returns):
/// each apex becomes a new vertex (with its marker) unless `input` still has a vertex there or
/// an earlier triangle made it (a pinch vertex, whose sectors are shielded one by one: the
/// subdomain's mesh keeps one vertex at it), each shielded triangle a triangle with
/// marker `triangle_marker`, the shield edge leaves r.mesh.segments and the two edges at the
/// apex join it with their input segments' markers (kept sorted).
/// The shield edges are found as the segments of `input` with pdd::shield_marker and matched
/// to `tris` by the coordinates of their endpoints (bitwise).
/// \returns the number of shield edges the kernel split (Theorem 24 (5) says 0); when it is
/// not 0 nothing is added (the triangles would not match the mesh).
/// \throws pdd::internal_error when a shield triangle has no shield edge in `input`.
/// Complexity O(m log m) in the mesh's segments, O(n log s) in the input's n vertices, plus
/// O(s log s) in the shields.
inline std::size_t add_shield_triangles(mesher_result& r, const pslg& input,
                                        const std::vector<shield_triangle>& tris,
                                        int triangle_marker) {
  if (tris.empty()) return 0;
  std::map<std::pair<double, double>, index_t> local;
  std::size_t splits = 0;
  for (std::size_t s = 0; s < input.segments.size(); ++s) {
    const segment& sg = input.segments[s];
    if (sg.marker != shield_marker) continue;
    if (std::binary_search(r.split_segments.begin(), r.split_segments.end(),
                           static_cast<index_t>(s)))
      ++splits;
    for (const index_t v : {sg.a, sg.b})
      local.emplace(std::pair{input.vertices[v].x, input.vertices[v].y}, v);
  }
  if (splits != 0) return splits;
  std::map<std::pair<double, double>, index_t> apexes; // no_index: not made yet
  for (const shield_triangle& t : tris)
    apexes.emplace(std::pair{t.apex.x, t.apex.y}, no_index);
  for (index_t v = 0; v < input.vertices.size(); ++v)
    if (const auto it = apexes.find({input.vertices[v].x, input.vertices[v].y}); it != apexes.end())
      it->second = v;
  triangle_mesh& m = r.mesh;
  std::erase_if(m.segments, [](const mesh_edge& e) { return e.marker == shield_marker; });
  for (const shield_triangle& t : tris) {
    const auto ib = local.find({t.b.x, t.b.y}), ic = local.find({t.c.x, t.c.y});
    if (ib == local.end() || ic == local.end())
      throw internal_error("a shielded triangle has no shield edge in its domain");
    index_t& apex = apexes.at({t.apex.x, t.apex.y});
    if (apex == no_index) {
      apex = static_cast<index_t>(m.vertices.size());
      m.vertices.push_back(t.apex);
      m.vertex_markers.push_back(t.apex_marker);
    }
    m.triangles.push_back({apex, ib->second, ic->second});
    m.triangle_markers.push_back(triangle_marker);
    m.segments.push_back({std::min(apex, ib->second), std::max(apex, ib->second), t.marker_ab});
    m.segments.push_back({std::min(apex, ic->second), std::max(apex, ic->second), t.marker_ac});
  }
  std::sort(m.segments.begin(), m.segments.end(), [](const mesh_edge& x, const mesh_edge& y) {
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
  return 0;
}

} // namespace pdd
