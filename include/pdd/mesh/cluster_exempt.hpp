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

/// The mesh edges along cluster segment [a, b], walked from the mesh vertex `from` at one of its
/// ends towards `to`, the other, as far as the mesh holds it (to the end in a mesh of the whole
/// domain; to the mesh's border in one subdomain's piece): from each vertex the incident edge
/// whose far end lies on the segment's line (verify's on_segment_line), strictly further along
/// it, nearest first. Needs no segment list (a mesh read from a file has none).
inline void walk_cluster_segment(const verify_impl::edge_table& table, const triangle_mesh& m,
                                 index_t from, const point& to,
                                 std::vector<std::array<index_t, 2>>& edges) {
  const point a = m.vertices[from];
  const double dx = to.x - a.x, dy = to.y - a.y, len2 = dx * dx + dy * dy;
  const auto param = [&](const point& q) { return ((q.x - a.x) * dx + (q.y - a.y) * dy) / len2; };
  index_t cur = from;
  double t_cur = 0.0;
  for (std::size_t step = 0; step < m.vertices.size() && t_cur < 1.0; ++step) {
    index_t next = verify_impl::none;
    double t_next = 2.0;
    table.for_each_incident(cur, [&](index_t k) {
      const verify_impl::edge_record& e = table.edges()[k];
      const index_t w = e.a == cur ? e.b : e.a;
      const point& q = m.vertices[w];
      const double t = q == to ? 1.0 : param(q);
      if (t <= t_cur || t > 1.0 || t >= t_next || !verify_impl::on_segment_line(a, to, q)) return;
      next = w, t_next = t;
    });
    if (next == verify_impl::none) return;
    edges.push_back({cur, next});
    cur = next, t_cur = t_next;
  }
}

/// The mesh edges (vertex pairs) on the cluster segments of g, walked from each end of each
/// that is a vertex of m (walk_cluster_segment).
inline std::vector<std::array<index_t, 2>>
cluster_mesh_edges(const triangle_mesh& m, const pslg& g,
                   const std::vector<std::pair<index_t, index_t>>& clusters) {
  std::vector<char> valid(m.triangles.size(), 1); // edge_table's precondition
  for (std::size_t t = 0; t < valid.size(); ++t) {
    const auto& tri = m.triangles[t];
    valid[t] = tri[0] < m.vertices.size() && tri[1] < m.vertices.size() &&
               tri[2] < m.vertices.size() && tri[0] != tri[1] && tri[1] != tri[2] &&
               tri[0] != tri[2];
  }
  const verify_impl::edge_table table(m, valid);
  verify_impl::vertex_lookup lookup;
  lookup.reserve(m.vertices.size());
  for (std::size_t v = 0; v < m.vertices.size(); ++v)
    lookup.try_emplace(m.vertices[v], static_cast<index_t>(v));
  std::vector<std::array<index_t, 2>> edges;
  for (const auto& [u, w] : clusters)
    for (const auto& [from, to] : {std::pair{u, w}, std::pair{w, u}}) {
      const auto it = lookup.find(g.vertices[from]);
      if (it != lookup.end()) walk_cluster_segment(table, m, it->second, g.vertices[to], edges);
    }
  return edges;
}

/// Per triangle of m: 1 when its smallest angle is below min_angle_deg.
inline std::vector<char> below_angle_bound(const triangle_mesh& m, double min_angle_deg) {
  std::vector<char> below(m.triangles.size(), 0);
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const auto& tri = m.triangles[t];
    if (tri[0] >= m.vertices.size() || tri[1] >= m.vertices.size() || tri[2] >= m.vertices.size())
      continue; // malformed: verify reports it
    const auto ang =
        triangle_angles_deg(m.vertices[tri[0]], m.vertices[tri[1]], m.vertices[tri[2]]);
    below[t] = std::min({ang[0], ang[1], ang[2]}) < min_angle_deg;
  }
  return below;
}
} // namespace detail

/// Per triangle of m, a mesh of domain g (domain_rule::triangle, not closed loops) or a piece of
/// one (a subdomain's mesh): 1 when its smallest angle is below min_angle_deg and it lies at a
/// small angle between g's segments (see the file comment). The mesh edges on the cluster
/// segments are found in the mesh itself (walked from the segments' ends that it holds), never
/// in m.segments, so a mesh read back from a file gets the same answer as the one in memory.
/// pdd::verify applies it by itself (pdd::find_quality_exempt_triangles).
/// Complexity O(T + V + C D + B E) for C cluster segments, D mesh vertices along them, B
/// triangles below the bound and E mesh edges on cluster segments (nothing is built when B = 0).
/// Thread-safe.
inline std::vector<char> find_cluster_exempt_triangles(const triangle_mesh& m, const pslg& g,
                                                       double min_angle_deg) {
  std::vector<char> exempt = detail::below_angle_bound(m, min_angle_deg);
  if (std::find(exempt.begin(), exempt.end(), 1) == exempt.end()) return exempt;
  const auto clusters = detail::cluster_segments(g);
  if (clusters.empty()) return std::vector<char>(m.triangles.size(), 0);
  const std::vector<std::array<index_t, 2>> edges = detail::cluster_mesh_edges(m, g, clusters);
  std::vector<char> on_cluster(m.vertices.size(), 0);
  for (const auto& [u, w] : edges)
    on_cluster[u] = on_cluster[w] = 1;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    if (!exempt[t]) continue;
    const auto& tri = m.triangles[t];
    if (on_cluster[tri[0]] || on_cluster[tri[1]] || on_cluster[tri[2]]) continue;
    const point &a = m.vertices[tri[0]], &b = m.vertices[tri[1]], &c = m.vertices[tri[2]];
    const auto k =
        CGAL::circumcenter(detail::verify_impl::to_cgal(a), detail::verify_impl::to_cgal(b),
                           detail::verify_impl::to_cgal(c));
    const point cc{k.x(), k.y()};
    exempt[t] = std::any_of(edges.begin(), edges.end(), [&](const std::array<index_t, 2>& e) {
      const point &p = m.vertices[e[0]], &q = m.vertices[e[1]];
      return (p.x - cc.x) * (q.x - cc.x) + (p.y - cc.y) * (q.y - cc.y) <= 0.0;
    });
  }
  return exempt;
}

} // namespace pdd
