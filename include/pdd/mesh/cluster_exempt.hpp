/// \file cluster_exempt.hpp
/// pdd::find_cluster_exempt_triangles: the triangles of a mesh of a domain that is not one of
/// closed loops that may stay below the angle bound, next to the small angles between its
/// segments (the exemption of pdd::cgal::mesher's cluster rule).
///
/// Why not shields there: pdd's shields (dissertation 8.1) are built on closed loops. A domain
/// with internal or dangling segments is meshed whole by the kernel, whose edge level is
/// CGAL's Refine_edges_with_clusters: the segments meeting at an angle < 60 deg form a cluster,
/// split on concentric shells round the apex (Shewchuk's remedy, as in Triangle), so that
/// refinement terminates; a bad triangle whose circumcentre encroaches a subsegment of a reduced
/// cluster, and whose shortest edge is longer than the cluster's, is left as it is
/// (kernels/cgal/detail/cluster_rule.hpp). The triangles so left are exactly what this finds,
/// up to the mesh's later state: a triangle below the bound is exempt when it has a vertex on a
/// cluster segment or its circumcentre lies in the closed diametral disk of a mesh edge on one.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_measures.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/geometry/domain_angles.hpp>
#include <pdd/mesh/detail/verify.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace pdd {

namespace detail {
/// The angle below which segments at a vertex form a cluster (CGAL's and Shewchuk's 60 deg).
inline constexpr double cluster_angle_deg = 60.0;

/// The segments (input vertex pairs) that bound a sector of the domain < 60 deg at a vertex.
inline std::vector<std::pair<index_t, index_t>> cluster_segments(const pslg& g) {
  std::vector<std::pair<index_t, index_t>> out;
  for (const domain_angle& a : domain_angles(g)) {
    if (a.angle_deg >= cluster_angle_deg) continue;
    out.emplace_back(a.vertex, a.from);
    out.emplace_back(a.vertex, a.to);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

/// True when q lies on segment [a, b] (verify's on_segment_line, within the segment's extent).
inline bool on_segment(const point& a, const point& b, const point& q) {
  const double t = (q.x - a.x) * (b.x - a.x) + (q.y - a.y) * (b.y - a.y);
  const double l2 = (b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y);
  return t >= 0.0 && t <= l2 && verify_impl::on_segment_line(a, b, q);
}
} // namespace detail

/// Per triangle of m, a mesh of domain g (domain_rule::triangle, not closed loops): 1 when its
/// smallest angle is below min_angle_deg and it lies at a small angle between g's segments (see
/// the file comment). Use it as verify_options::quality_exempt.
/// Complexity O(S_m C + T + B E) for S_m mesh segment edges, C cluster segments, B triangles
/// below the bound and E mesh edges on cluster segments. Thread-safe.
inline std::vector<char> find_cluster_exempt_triangles(const triangle_mesh& m, const pslg& g,
                                                       double min_angle_deg) {
  std::vector<char> exempt(m.triangles.size(), 0);
  const auto clusters = detail::cluster_segments(g);
  if (clusters.empty()) return exempt;
  std::vector<char> on_cluster(m.vertices.size(), 0);
  std::vector<std::array<point, 2>> edges;
  for (const mesh_edge& e : m.segments)
    for (const auto& [u, w] : clusters) {
      const point &a = g.vertices[u], &b = g.vertices[w];
      if (!detail::on_segment(a, b, m.vertices[e.a]) || !detail::on_segment(a, b, m.vertices[e.b]))
        continue;
      on_cluster[e.a] = on_cluster[e.b] = 1;
      edges.push_back({m.vertices[e.a], m.vertices[e.b]});
    }
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto& tri = m.triangles[t];
    const point &a = m.vertices[tri[0]], &b = m.vertices[tri[1]], &c = m.vertices[tri[2]];
    const auto ang = detail::triangle_angles_deg(a, b, c);
    if (std::min({ang[0], ang[1], ang[2]}) >= min_angle_deg) continue;
    if (on_cluster[tri[0]] || on_cluster[tri[1]] || on_cluster[tri[2]]) {
      exempt[t] = 1;
      continue;
    }
    const auto k =
        CGAL::circumcenter(detail::verify_impl::to_cgal(a), detail::verify_impl::to_cgal(b),
                           detail::verify_impl::to_cgal(c));
    const point cc{k.x(), k.y()};
    for (const auto& e : edges)
      if ((e[0].x - cc.x) * (e[1].x - cc.x) + (e[0].y - cc.y) * (e[1].y - cc.y) <= 0.0) {
        exempt[t] = 1;
        break;
      }
  }
  return exempt;
}

} // namespace pdd
