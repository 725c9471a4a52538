/// \file verify_checks.hpp
/// Implementation of pdd::verify: the parallel triangle and edge checks, the reports of
/// duplicate vertices, missing segments and bad edges, the mesh area, and verify_run, which
/// runs them in the documented order.
#pragma once

#include <pdd/core/kernel.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/core/triangle_measures.hpp>
#include <pdd/core/triangle_mesh.hpp>
#include <pdd/geometry/domain_faces.hpp>
#include <pdd/geometry/loops.hpp>
#include <pdd/mesh/detail/verify.hpp>
#include <pdd/mesh/verification_report.hpp>
#include <pdd/parallel/deterministic_reduce.hpp>
#include <pdd/parallel/parallel_for.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace pdd::detail {

/// Collects violations: counts all, describes the first max_reported.
struct violation_sink {
  verification_report& r;
  std::size_t max_reported;
  template <class Describe>
  void add(std::size_t& counter, Describe&& describe) {
    ++counter;
    if (r.messages.size() < max_reported) r.messages.push_back(describe());
  }
};

/// Per-triangle results (bit flags), computed in parallel.
enum triangle_flag : std::uint8_t {
  tri_malformed = 1,
  tri_orientation = 2,
  tri_quality = 4,
  tri_area = 8
};

/// The flags of every triangle; o.quality_exempt as given (absent: none exempt; pdd::verify
/// resolves its default before).
template <class AreaBound>
std::vector<std::uint8_t> check_triangles(const triangle_mesh& m, const verify_options& o,
                                          const AreaBound& bound_at) {
  namespace vi = verify_impl;
  const std::size_t nv = m.vertices.size();
  std::vector<std::uint8_t> flags(m.triangles.size(), 0);
  static const std::vector<char> none_exempt;
  const std::vector<char>& exempt = o.quality_exempt ? *o.quality_exempt : none_exempt;
  // the smallest angle below min_angle_deg - 1e-9: by its squared sine (no atan2 per triangle;
  // the sine is monotone up to 90 deg, and no triangle's smallest angle exceeds 60)
  const double min_angle = o.criteria.min_angle_deg - 1e-9;
  const double bound_sine = std::sin(std::min(min_angle, 90.0) * std::numbers::pi / 180.0);
  const double bound_sine2 = bound_sine * bound_sine;
  const auto below_angle = [&](const point& a, const point& b, const point& c) {
    return min_angle > 0.0 && !(squared_sine_min_angle(a, b, c) >= bound_sine2); // NaN: below
  };
  parallel_ranges(flags.size(), 1024, [&](std::size_t first, std::size_t last) {
    for (std::size_t t = first; t != last; ++t) {
      const auto& tri = m.triangles[t];
      if (tri[0] >= nv || tri[1] >= nv || tri[2] >= nv || tri[0] == tri[1] || tri[1] == tri[2] ||
          tri[0] == tri[2]) {
        flags[t] = tri_malformed;
        continue;
      }
      const point& a = m.vertices[tri[0]];
      const point& b = m.vertices[tri[1]];
      const point& c = m.vertices[tri[2]];
      std::uint8_t f = 0;
      if (CGAL::orientation(vi::to_cgal(a), vi::to_cgal(b), vi::to_cgal(c)) != CGAL::LEFT_TURN)
        f |= tri_orientation;
      if (below_angle(a, b, c) && !(t < exempt.size() && exempt[t])) f |= tri_quality;
      const double bound = std::min(o.criteria.max_area, bound_at(triangle_centroid(a, b, c)));
      if (triangle_area(a, b, c) > bound * (1.0 + 1e-12)) f |= tri_area;
      flags[t] = f;
    }
  });
  return flags;
}

inline void report_triangles(const triangle_mesh& m, const std::vector<std::uint8_t>& flags,
                             violation_sink& sink) {
  using verify_impl::str;
  verification_report& r = sink.r;
  for (std::size_t t = 0; t < flags.size(); ++t) {
    if (flags[t] == 0) continue;
    const auto& tri = m.triangles[t];
    const auto name = [&] {
      std::string s = "triangle " + std::to_string(t) + " (" + std::to_string(tri[0]) + ", " +
                      std::to_string(tri[1]) + ", " + std::to_string(tri[2]) + ")";
      if (flags[t] & tri_malformed) return s;
      return s + " at " + str(m.vertices[tri[0]]) + " " + str(m.vertices[tri[1]]) + " " +
             str(m.vertices[tri[2]]);
    };
    if (flags[t] & tri_malformed)
      sink.add(r.orientation_violations, [&] { return name() + ": bad vertex indices"; });
    if (flags[t] & tri_orientation)
      sink.add(r.orientation_violations, [&] { return name() + ": clockwise or degenerate"; });
    if (flags[t] & tri_quality)
      sink.add(r.quality_violations, [&] {
        const auto& v = m.vertices;
        const auto ang = triangle_angles_deg(v[tri[0]], v[tri[1]], v[tri[2]]);
        return name() + ": smallest angle " + std::to_string(std::min({ang[0], ang[1], ang[2]})) +
               " deg";
      });
    if (flags[t] & tri_area)
      sink.add(r.area_violations, [&] { return name() + ": area above the bound"; });
  }
}

/// Finds coinciding vertices; returns the coordinates -> first vertex table.
inline verify_impl::vertex_lookup report_duplicates(const triangle_mesh& m, violation_sink& sink) {
  verify_impl::vertex_lookup lookup;
  lookup.reserve(m.vertices.size());
  for (std::size_t v = 0; v < m.vertices.size(); ++v) {
    const auto inserted = lookup.emplace(m.vertices[v], static_cast<index_t>(v));
    if (!inserted.second)
      sink.add(sink.r.duplicate_vertices, [&] {
        const index_t first = inserted.first->second;
        return "vertex " + std::to_string(v) + " duplicates vertex " + std::to_string(first) +
               " at " + verify_impl::str(m.vertices[v]);
      });
  }
  return lookup;
}

/// Per-edge results, in parallel: 1 nonmanifold (in > 2 triangles, or twice in the same
/// direction), 2 not locally Delaunay (exact in-circle test), 0 otherwise.
inline std::vector<std::uint8_t> check_edges(const triangle_mesh& m,
                                             const verify_impl::edge_table& table) {
  namespace vi = verify_impl;
  const auto& edges = table.edges();
  std::vector<std::uint8_t> flags(edges.size(), 0);
  parallel_ranges(edges.size(), 1024, [&](std::size_t first, std::size_t last) {
    for (std::size_t k = first; k != last; ++k) {
      const vi::edge_record& e = edges[k];
      if (e.count > 2 || (e.count == 2 && e.forward[0] == e.forward[1])) {
        flags[k] = 1;
        continue;
      }
      if (e.count != 2) continue;
      const auto apex = [&](index_t t) {
        const auto& tri = m.triangles[t];
        return tri[0] != e.a && tri[0] != e.b   ? tri[0]
               : tri[1] != e.a && tri[1] != e.b ? tri[1]
                                                : tri[2];
      };
      const auto p = vi::to_cgal(m.vertices[e.a]), q = vi::to_cgal(m.vertices[e.b]);
      const auto s0 = vi::to_cgal(m.vertices[apex(e.tri[0])]);
      const auto s1 = vi::to_cgal(m.vertices[apex(e.tri[1])]);
      // Strictly inside the circle through p, q, s0 (side_of_oriented_circle has a static
      // filter in Epick; side_of_bounded_circle does not).
      const CGAL::Orientation o = CGAL::orientation(p, q, s0);
      if (o == CGAL::COLLINEAR) continue; // reported as a degenerate triangle
      const auto side = o == CGAL::LEFT_TURN ? CGAL::side_of_oriented_circle(p, q, s0, s1)
                                             : CGAL::side_of_oriented_circle(q, p, s0, s1);
      if (side == CGAL::ON_POSITIVE_SIDE) flags[k] = 2;
    }
  });
  return flags;
}

/// True when segment sg of d (domain_rule::triangle) has no domain face on either side: a
/// dangling segment in the unbounded face or in a hole, left out of the mesh as Triangle does.
/// The faces are built on the first call only (faces holds them).
inline bool outside_domain(const pslg& d, const segment& sg, std::optional<domain_faces>& faces) {
  if (d.rule != domain_rule::triangle) return false;
  if (sg.a >= d.vertices.size() || sg.b >= d.vertices.size() || sg.a == sg.b) return false;
  if (!faces) faces.emplace(d);
  return !faces->touches_domain(sg.a, sg.b);
}

/// Walks every input segment along mesh edges (marking them) and reports those that fail
/// (except, by Triangle's rule, segments with no domain face on either side).
inline void report_segments(const triangle_mesh& m, const pslg& d,
                            const verify_impl::vertex_lookup& lookup,
                            verify_impl::edge_table& table, violation_sink& sink) {
  namespace vi = verify_impl;
  const auto find = [&](index_t v) {
    if (v >= d.vertices.size()) return vi::none;
    const auto it = lookup.find(d.vertices[v]);
    return it == lookup.end() ? vi::none : it->second;
  };
  std::vector<index_t> path;
  std::optional<domain_faces> faces; // built only when a segment is not found
  for (std::size_t s = 0; s < d.segments.size(); ++s) {
    const segment& sg = d.segments[s];
    const index_t ma = find(sg.a), mb = find(sg.b);
    if (ma != vi::none && mb != vi::none && ma != mb && vi::walk_segment(table, m, ma, mb, path))
      continue;
    if (outside_domain(d, sg, faces)) continue;
    sink.add(sink.r.missing_segments, [&] {
      std::string msg = "segment " + std::to_string(s) + " (" + std::to_string(sg.a) + ", " +
                        std::to_string(sg.b) + ")";
      if (sg.a < d.vertices.size() && sg.b < d.vertices.size())
        msg += " from " + vi::str(d.vertices[sg.a]) + " to " + vi::str(d.vertices[sg.b]);
      return msg + ": not a union of mesh edges";
    });
  }
}

/// Reports the isolated input vertices (on no segment) that lie inside the domain but are no
/// vertex of a mesh triangle (domain_rule::triangle; odd nesting has closed loops only). The
/// domain's faces are located only when there are such vertices.
inline void report_isolated_vertices(const pslg& d, const verify_impl::vertex_lookup& lookup,
                                     const verify_impl::edge_table& table, violation_sink& sink) {
  if (d.rule != domain_rule::triangle) return;
  std::vector<char> on_segment(d.vertices.size(), 0);
  for (const segment& sg : d.segments)
    for (const index_t v : {sg.a, sg.b})
      if (v < on_segment.size()) on_segment[v] = 1;
  if (std::find(on_segment.begin(), on_segment.end(), 0) == on_segment.end()) return;
  const domain_faces faces(d);
  for (std::size_t v = 0; v < d.vertices.size(); ++v) {
    if (on_segment[v]) continue;
    const auto it = lookup.find(d.vertices[v]);
    bool used = false;
    if (it != lookup.end()) table.for_each_incident(it->second, [&](index_t) { used = true; });
    if (used || !faces.touches_domain(static_cast<index_t>(v))) continue;
    sink.add(sink.r.missing_vertices, [&] {
      return "input vertex " + std::to_string(v) + " at " + verify_impl::str(d.vertices[v]) +
             " lies inside the domain but is no vertex of the mesh";
    });
  }
}

/// Reports nonmanifold edges, boundary edges on no segment and non-Delaunay edges (on input
/// segments only when `segments_delaunay`: a mesh refined under the diametral lens is
/// constrained Delaunay, see pdd::segment_encroachment).
inline void report_edges(const triangle_mesh& m, const verify_impl::edge_table& table,
                         const std::vector<std::uint8_t>& flags, bool segments_delaunay,
                         violation_sink& sink) {
  namespace vi = verify_impl;
  verification_report& r = sink.r;
  const auto& edges = table.edges();
  for (std::size_t k = 0; k < edges.size(); ++k) {
    const vi::edge_record& e = edges[k];
    const auto name = [&] {
      return "edge (" + std::to_string(e.a) + ", " + std::to_string(e.b) + ") from " +
             vi::str(m.vertices[e.a]) + " to " + vi::str(m.vertices[e.b]);
    };
    if (flags[k] == 1)
      sink.add(r.nonmanifold_edges, [&] {
        return name() + ": in " + std::to_string(e.count) + " triangles" +
               (e.count == 2 ? " with the same direction" : "");
      });
    else if (e.count == 1 && !e.on_segment)
      sink.add(r.nonmanifold_edges, [&] { return name() + ": boundary edge on no input segment"; });
    if (flags[k] == 2 && (segments_delaunay || !e.on_segment))
      sink.add(r.delaunay_violations, [&] {
        return name() + ": not locally Delaunay (triangles " + std::to_string(e.tri[0]) + ", " +
               std::to_string(e.tri[1]) + ")";
      });
  }
}

/// Sum of the areas of the well-formed triangles: a deterministic parallel reduction.
inline double mesh_area(const triangle_mesh& m, const std::vector<std::uint8_t>& flags) {
  return deterministic_reduce(
      m.triangles.size(), 0.0,
      [&](double& acc, std::size_t begin, std::size_t end) {
        for (std::size_t t = begin; t != end; ++t)
          if (!(flags[t] & tri_malformed)) {
            const auto& tri = m.triangles[t];
            acc += triangle_area(m.vertices[tri[0]], m.vertices[tri[1]], m.vertices[tri[2]]);
          }
      },
      [](double& into, double from) { into += from; });
}

template <class AreaBound>
verification_report verify_run(const triangle_mesh& m, const pslg& d, const verify_options& o,
                               const AreaBound& bound_at) {
  verification_report r;
  violation_sink sink{r, o.max_reported};
  const std::vector<std::uint8_t> tri_flags = check_triangles(m, o, bound_at);
  report_triangles(m, tri_flags, sink);
  const verify_impl::vertex_lookup lookup = report_duplicates(m, sink);
  std::vector<char> valid(tri_flags.size());
  for (std::size_t t = 0; t < valid.size(); ++t)
    valid[t] = !(tri_flags[t] & tri_malformed);
  verify_impl::edge_table table(m, valid);
  const std::vector<std::uint8_t> edge_flags = check_edges(m, table);
  report_segments(m, d, lookup, table, sink);
  report_isolated_vertices(d, lookup, table, sink);
  report_edges(m, table, edge_flags,
               o.criteria.encroachment == segment_encroachment::diametral_circle, sink);
  r.area_mesh = mesh_area(m, tri_flags);
  r.area_domain = domain_area(d);
  r.area_ok = std::abs(r.area_mesh - r.area_domain) <= o.area_tolerance * std::abs(r.area_domain);
  if (!r.area_ok && r.messages.size() < o.max_reported)
    r.messages.push_back("mesh area " + std::to_string(r.area_mesh) + " differs from domain area " +
                         std::to_string(r.area_domain));
  return r;
}

} // namespace pdd::detail
