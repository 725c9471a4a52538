/// \file cluster_exempt.hpp
/// pdd::find_cluster_exempt_triangles: the triangles of a mesh of a domain that is not one of
/// closed loops that may stay below the angle bound, at the small angles between its segments
/// (the exemption of the kernels' rules for small input angles).
///
/// Why not shields there: pdd's shields (dissertation 8.1) are built on closed loops. A domain
/// with internal or dangling segments is meshed whole by the kernel, which treats a small angle
/// between segments (< 60 deg) as Ruppert's concentric shells and Shewchuk's rules do, so that
/// refinement terminates, and leaves two kinds of triangles below the bound there:
///  - CGAL's kernel (Refine_edges_with_clusters, kernels/cgal/detail/cluster_rule.hpp): the
///    segments meeting at the apex form a cluster, whose subsegments at the apex are split on
///    shells; a bad triangle whose circumcentre encroaches one of them once the cluster is
///    reduced is left. Its circumcentre lies in the closed diametral disk of a mesh edge at the
///    apex along a segment of the small angle: within the cluster's shell radius of the apex.
///  - The native kernel (kernels/native/detail/refine.hpp): a triangle bad only in shape whose
///    shortest edge joins vertices on the two segments of the small angle at the same distance
///    from the apex (one shell; squared distances within 2%) is left: its small angle is forced
///    by the input angle.
/// Exactly these are exempt; a bad triangle elsewhere, beside a segment of a small angle but
/// away from its apex's shells, is reported.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_measures.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/geometry/domain_angles.hpp>
#include <pdd/mesh/detail/verify.hpp>

#include <algorithm>
#include <array>
#include <compare>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <utility>
#include <vector>

namespace pdd {

namespace detail {
/// The angle below which segments at a vertex form a cluster (CGAL's and Shewchuk's 60 deg).
inline constexpr double cluster_angle_deg = 60.0;

/// A sector of the domain below 60 deg: its apex and the far ends of its two segments (PSLG
/// vertex ids).
struct small_sector {
  index_t apex = no_index; ///< the apex
  index_t a = no_index;    ///< the far end of the segment the sector starts from
  index_t b = no_index;    ///< the far end of the segment it ends at
};

/// The sectors of g's domain below cluster_angle_deg (pdd::domain_angles).
inline std::vector<small_sector> small_sectors(const pslg& g) {
  std::vector<small_sector> out;
  for (const domain_angle& a : domain_angles(g))
    if (a.angle_deg < cluster_angle_deg && a.from != a.to) out.push_back({a.vertex, a.from, a.to});
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

/// A mesh vertex on a segment of a small sector (not its apex): the sector and which segment.
struct sector_vertex {
  index_t vertex = no_index; ///< the mesh vertex
  std::uint32_t sector = 0;  ///< index in small_sectors
  std::uint8_t side = 0;     ///< 0: the segment to small_sector::a, 1: to b
  auto operator<=>(const sector_vertex&) const = default;
};

/// What the exemption needs of the mesh at the small sectors: the mesh vertices on their
/// segments (sorted by vertex), and the mesh edges at their apexes along those segments.
struct small_angle_marks {
  std::vector<sector_vertex> on_sides;            ///< sorted
  std::vector<std::array<index_t, 2>> apex_edges; ///< the first edge from each apex it holds
};

/// The mesh edges along segment [apex, far] that m holds: walked from the apex when m holds it
/// (the first edge is then the apex's), and from the far end when m holds that.
inline void walk_sector_side(const verify_impl::edge_table& table, const triangle_mesh& m,
                             const verify_impl::vertex_lookup& lookup, const point& apex,
                             const point& far, small_angle_marks& marks,
                             std::vector<std::array<index_t, 2>>& edges) {
  edges.clear();
  if (const auto it = lookup.find(apex); it != lookup.end()) {
    walk_cluster_segment(table, m, it->second, far, edges);
    if (!edges.empty()) marks.apex_edges.push_back(edges.front());
  }
  if (const auto it = lookup.find(far); it != lookup.end())
    walk_cluster_segment(table, m, it->second, apex, edges);
}

/// The small_angle_marks of m for the sectors of g (segments walked in the mesh itself,
/// walk_cluster_segment).
inline small_angle_marks mark_small_angles(const triangle_mesh& m, const pslg& g,
                                           const std::vector<small_sector>& sectors) {
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
  small_angle_marks marks;
  std::vector<std::array<index_t, 2>> edges;
  for (std::size_t k = 0; k < sectors.size(); ++k)
    for (std::uint8_t side = 0; side < 2; ++side) {
      const point& apex = g.vertices[sectors[k].apex];
      walk_sector_side(table, m, lookup, apex, g.vertices[side ? sectors[k].b : sectors[k].a],
                       marks, edges);
      for (const auto& e : edges)
        for (const index_t v : e)
          if (!(m.vertices[v] == apex))
            marks.on_sides.push_back({v, static_cast<std::uint32_t>(k), side});
    }
  std::sort(marks.on_sides.begin(), marks.on_sides.end());
  marks.on_sides.erase(std::unique(marks.on_sides.begin(), marks.on_sides.end()),
                       marks.on_sides.end());
  return marks;
}

/// The sector marks of mesh vertex v.
inline std::span<const sector_vertex> marks_of(const small_angle_marks& marks, index_t v) {
  const auto lo = std::lower_bound(marks.on_sides.begin(), marks.on_sides.end(), v,
                                   [](const sector_vertex& s, index_t x) { return s.vertex < x; });
  auto hi = lo;
  while (hi != marks.on_sides.end() && hi->vertex == v)
    ++hi;
  return {lo, hi};
}

/// The native kernel's rule: the shortest edge of triangle `tri` joins vertices on the two
/// segments of one small sector at the same distance from its apex (squared distances within
/// 2%, as kernels/native/detail/refine.hpp decides).
inline bool across_one_shell(const triangle_mesh& m, const pslg& g,
                             const std::vector<small_sector>& sectors,
                             const small_angle_marks& marks, const std::array<index_t, 3>& tri) {
  int k = 0;
  double shortest = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    const double l = squared_distance(m.vertices[tri[(i + 1) % 3]], m.vertices[tri[(i + 2) % 3]]);
    if (l < shortest) shortest = l, k = i;
  }
  const index_t p = tri[(k + 1) % 3], q = tri[(k + 2) % 3];
  for (const sector_vertex& sp : marks_of(marks, p))
    for (const sector_vertex& sq : marks_of(marks, q)) {
      if (sp.sector != sq.sector || sp.side == sq.side) continue;
      const point& apex = g.vertices[sectors[sp.sector].apex];
      const double ratio =
          squared_distance(apex, m.vertices[p]) / squared_distance(apex, m.vertices[q]);
      if (ratio > 0.98 && ratio < 1.02) return true;
    }
  return false;
}

/// CGAL's cluster rule: the circumcentre of triangle `tri` lies in the closed diametral disk
/// of a mesh edge at a small sector's apex along one of its segments.
inline bool circumcentre_at_an_apex(const triangle_mesh& m, const small_angle_marks& marks,
                                    const std::array<index_t, 3>& tri) {
  const point &a = m.vertices[tri[0]], &b = m.vertices[tri[1]], &c = m.vertices[tri[2]];
  const auto k =
      CGAL::circumcenter(verify_impl::to_cgal(a), verify_impl::to_cgal(b), verify_impl::to_cgal(c));
  const point cc{k.x(), k.y()};
  return std::any_of(marks.apex_edges.begin(), marks.apex_edges.end(),
                     [&](const std::array<index_t, 2>& e) {
                       const point &p = m.vertices[e[0]], &q = m.vertices[e[1]];
                       return (p.x - cc.x) * (q.x - cc.x) + (p.y - cc.y) * (q.y - cc.y) <= 0.0;
                     });
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
/// one (a subdomain's mesh): 1 when its smallest angle is below min_angle_deg and it is one the
/// kernels' small-angle rules leave (see the file comment): its shortest edge crosses a small
/// sector on one shell, or its circumcentre lies in the diametral disk of a mesh edge at the
/// sector's apex. The mesh edges on the sectors' segments are found in the mesh itself (walked
/// from the segments' ends that it holds), never in m.segments, so a mesh read back from a file
/// gets the same answer as the one in memory. pdd::verify applies it by itself
/// (pdd::find_quality_exempt_triangles).
/// Complexity O(T + V + C D + B (A + log V)) for C small sectors, D mesh vertices along their
/// segments, B triangles below the bound and A apex edges (nothing is built when B = 0).
/// Thread-safe.
inline std::vector<char> find_cluster_exempt_triangles(const triangle_mesh& m, const pslg& g,
                                                       double min_angle_deg) {
  std::vector<char> exempt = detail::below_angle_bound(m, min_angle_deg);
  if (std::find(exempt.begin(), exempt.end(), 1) == exempt.end()) return exempt;
  const std::vector<detail::small_sector> sectors = detail::small_sectors(g);
  if (sectors.empty()) return std::vector<char>(m.triangles.size(), 0);
  const detail::small_angle_marks marks = detail::mark_small_angles(m, g, sectors);
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    if (exempt[t])
      exempt[t] = detail::across_one_shell(m, g, sectors, marks, m.triangles[t]) ||
                  detail::circumcentre_at_an_apex(m, marks, m.triangles[t]);
  return exempt;
}

} // namespace pdd
