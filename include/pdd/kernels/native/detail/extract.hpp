/// \file extract.hpp
/// The mesher_result of a refined native triangulation.
#pragma once

#include <pdd/concepts/delaunay_mesher.hpp>
#include <pdd/kernels/native/detail/segments.hpp>
#include <pdd/kernels/native/detail/triangulation.hpp>

#include <algorithm>
#include <utility>
#include <vector>

namespace pdd::detail::native_mesh {

/// Input vertices first (coordinates and markers copied), then the Steiner vertices in
/// insertion order (the bounding triangle's three vertices are dropped); a Steiner vertex on
/// an input segment gets the segment's marker. Triangles: the in-domain ones in slot order.
/// Segments: the constrained edges with a domain side, sorted, with their segment's marker.
/// Takes tr's vertices (it is left without them).
inline mesher_result extract(triangulation& tr, const segment_ids& ids, const pslg& d) {
  const auto n = static_cast<index_t>(d.vertices.size());
  const auto out = [n](index_t v) { return v < n ? v : v - 3; };
  const auto marker_of = [&d](index_t s) { return s == no_index ? 0 : d.segments[s].marker; };
  mesher_result r;
  triangle_mesh& m = r.mesh;
  m.vertex_markers.reserve(tr.pts.size() - 3);
  m.vertex_markers.assign(d.vertex_markers.begin(), d.vertex_markers.end());
  m.vertex_markers.resize(n, 0);
  for (std::size_t v = n + 3; v < tr.pts.size(); ++v)
    m.vertex_markers.push_back(marker_of(ids.of_vertex[v]));
  std::size_t in_domain = 0;
  for (std::uint32_t t = 0; t < tr.size(); ++t)
    in_domain += tr.in_domain(t) ? 1 : 0;
  m.triangles.reserve(in_domain);
  for (std::uint32_t t = 0; t < tr.size(); ++t) {
    if (!tr.in_domain(t)) continue;
    m.triangles.push_back({out(tr.corner(t)[0]), out(tr.corner(t)[1]), out(tr.corner(t)[2])});
    for (int i = 0; i < 3; ++i) {
      const ref_t nb = tr.adj(t)[i];
      if (!tr.constrained(t, i) || (tr.in_domain(ref_tri(nb)) && ref_tri(nb) < t)) continue;
      const index_t a = tr.corner(t)[next3(i)], b = tr.corner(t)[prev3(i)];
      m.segments.push_back(
          {std::min(out(a), out(b)), std::max(out(a), out(b)), marker_of(ids.of_edge(a, b))});
    }
  }
  m.triangle_markers.assign(m.triangles.size(), 0);
  std::sort(m.segments.begin(), m.segments.end(), [](const mesh_edge& x, const mesh_edge& y) {
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
  for (std::size_t s = 0; s < d.segments.size(); ++s) {
    const ref_t e = tr.find_edge(d.segments[s].a, d.segments[s].b);
    if (e == no_ref || !tr.constrained(ref_tri(e), ref_edge(e)))
      r.split_segments.push_back(static_cast<index_t>(s));
  }
  // The coordinates move over (the input vertices are d's, unchanged): without the bounding
  // triangle's three, in place, instead of a copy that touched as much new memory again.
  m.vertices = std::move(tr.pts);
  m.vertices.erase(m.vertices.begin() + n, m.vertices.begin() + n + 3);
  return r;
}

} // namespace pdd::detail::native_mesh
