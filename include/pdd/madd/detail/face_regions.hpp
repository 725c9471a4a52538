/// \file face_regions.hpp
/// Implementation detail of MADD on a general PSLG (one not of closed loops, issue 13): its
/// faces (pdd::domain_faces, by the PSLG's rule) as the first regions, each a polygon with
/// holes whose loops are walked along the segments around it. Where a face touches itself (a
/// pinch vertex: an island touching the shore, two holes touching), its loops are weakly
/// simple: they visit that vertex once per sector of the face there, and MADD keeps the visits
/// apart (madd/detail/triangulation.hpp), so each subdomain meets the vertex in its own
/// sectors and each sector is shielded on its own. A segment between two faces of
/// the domain (an internal constraint) is then an edge of both regions: MADD keeps their
/// vertices conforming (apply_edge_splits) and assemble_decomposition makes it an interface,
/// so the decoupling path splits it like a separator. A segment with one face on both sides
/// (dangling, or joining two points of the face's boundary) and an isolated vertex are
/// features of their face's region (madd_feature): MADD keeps every separator away from them
/// (madd/detail/features.hpp), so each ends up inside one subdomain and its kernel meshes it.
/// Where a small angle lies on a segment between two faces, the vertex gets a cap
/// (madd/detail/corner_caps.hpp): the regions are then the faces of the capped PSLG, the
/// sectors of each cap joined into one region kept whole. The walk is madd/detail/face_walk.hpp.
#pragma once

#include <pdd/core/pslg.hpp>
#include <pdd/errors.hpp>
#include <pdd/geometry/domain_faces.hpp>
#include <pdd/geometry/properties.hpp>
#include <pdd/madd/detail/corner_caps.hpp>
#include <pdd/madd/detail/face_walk.hpp>
#include <pdd/madd/detail/region.hpp>

#include <algorithm>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace pdd::detail {

/// The faces of a general PSLG as MADD regions: one per face, with caps (kept whole) around
/// the vertices where a small angle lies on a segment between two faces.
struct face_region_set {
  std::vector<madd_region> regions;           ///< in face order, the caps among them
  std::size_t faces = 0;                      ///< faces of the domain (pdd::domain_faces)
  std::vector<std::pair<point, double>> caps; ///< each cap's apex and radius
  /// Empty without caps; else how many there are and why, naming the first apex.
  std::string cap_reason;
};

/// The face beyond the boundary edge a -> b of a face (the face of its twin b -> a when a -> b
/// is an internal constraint: boundary_by_edge is face_boundaries sorted by edge), no_index
/// when a -> b has no face of the domain beyond it.
inline index_t face_beyond(const std::vector<face_half_edge>& boundary_by_edge, index_t a,
                           index_t b) {
  const auto it =
      std::lower_bound(boundary_by_edge.begin(), boundary_by_edge.end(), face_half_edge{b, a, 0});
  return it != boundary_by_edge.end() && it->a == b && it->b == a ? it->face : no_index;
}

/// Two faces to join into one region, and the vertex where a small angle asks for it.
struct face_join {
  index_t face, beyond, vertex;
};

/// The joins that the corner of `loop` (of `face`) at position i asks for: where it is below
/// 60 deg, one across each side that is an internal constraint. An interface there would meet
/// the subdomain's boundary at < Phi0 and no shield fits between two faces; a cap around the
/// vertex (detail::cap_corners) holds the piece of the segment there inside one region.
inline void join_small_corner(const pslg& g, index_t face, const std::vector<index_t>& loop,
                              std::size_t i, const std::vector<face_half_edge>& boundary_by_edge,
                              std::vector<face_join>& joins) {
  const std::size_t n = loop.size();
  const index_t prev = loop[(i + n - 1) % n], v = loop[i], next = loop[(i + 1) % n];
  // the angle as the shields measure it (detail::shield_angles), so that no corner a
  // subdomain would have to shield is left on an interface by rounding
  if (ccw_angle_deg(g.vertices[v], g.vertices[next], g.vertices[prev]) >= 60.0) return;
  for (const index_t beyond :
       {face_beyond(boundary_by_edge, prev, v), face_beyond(boundary_by_edge, v, next)})
    if (beyond != no_index) joins.push_back({face, beyond, v});
}

/// The joins that the segment features of `face` ask for where one starts at a vertex of its
/// loops at an angle below 60 deg to an internal constraint there (an interface, which the
/// kernel's refinement around that small angle may split): one across that constraint. A
/// feature from the apex of a corner below 60 deg between external segments needs none: that
/// corner is then not shielded, and the subdomain's kernel meshes its small angles
/// (detail::subdomain_small_angles).
inline void join_features_at_corners(const pslg& g, index_t face,
                                     const std::vector<std::vector<index_t>>& loops,
                                     const std::vector<madd_feature>& features,
                                     const std::vector<face_half_edge>& boundary_by_edge,
                                     std::vector<face_join>& joins) {
  std::vector<std::pair<point, point>> ends; // (one end, the other end), sorted
  for (const madd_feature& f : features)
    if (!f.is_vertex()) {
      ends.emplace_back(f.a, f.b);
      ends.emplace_back(f.b, f.a);
    }
  std::sort(ends.begin(), ends.end());
  const auto by_end = [](const std::pair<point, point>& e, point p) { return e.first < p; };
  for (const auto& loop : loops)
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const index_t prev = loop[(i + loop.size() - 1) % loop.size()], v = loop[i],
                    next = loop[(i + 1) % loop.size()];
      const point pv = g.vertices[v];
      const index_t before = face_beyond(boundary_by_edge, prev, v),
                    after = face_beyond(boundary_by_edge, v, next);
      for (auto it = std::lower_bound(ends.begin(), ends.end(), pv, by_end);
           it != ends.end() && it->first == pv; ++it) {
        if (before != no_index && angle_deg(pv, it->second, g.vertices[prev]) < 60.0)
          joins.push_back({face, before, v});
        if (after != no_index && angle_deg(pv, it->second, g.vertices[next]) < 60.0)
          joins.push_back({face, after, v});
      }
    }
}

/// The loops of one face (or group of faces: `face` is its representative).
struct face_loops {
  index_t face;
  std::vector<std::vector<index_t>> loops;
};

/// Walks the loops of every face (or group of faces) of `tris` (sorted boundary half-edges
/// `edges`, `by_edge` by edge), and collects the joins their small angles ask for.
inline std::vector<face_join>
small_angle_joins(const pslg& g, const std::vector<face_half_edge>& edges,
                  const std::vector<face_half_edge>& by_edge,
                  const std::vector<std::vector<madd_feature>>& features,
                  std::vector<face_loops>& loops_of) {
  std::vector<face_join> joins;
  loops_of.clear();
  for (std::size_t first = 0, last = 0; first < edges.size(); first = last) {
    const index_t face = edges[first].face;
    while (last < edges.size() && edges[last].face == face)
      ++last;
    loops_of.push_back({face, {}});
    std::vector<std::vector<index_t>>& loops = loops_of.back().loops;
    walk_face_loops(g, edges, first, last, loops);
    for (const auto& loop : loops)
      for (std::size_t i = 0; i < loop.size(); ++i)
        join_small_corner(g, face, loop, i, by_edge, joins);
    join_features_at_corners(g, face, loops, features[face], by_edge, joins);
  }
  return joins;
}

/// What face_region_set::cap_reason says of `count` caps, the first at `first`.
inline std::string caps_text(const pslg& g, std::size_t count, index_t first) {
  if (count == 0) return {};
  return std::to_string(count) + " cap(s) (the first at " + vertex_name(g, first) +
         "): a corner below 60 deg on a segment between two faces, or a segment inside a face "
         "at below 60 deg to one, lies inside a cap, one subdomain whose kernel meshes the "
         "small angle";
}

/// The faces of g (`faces`), joined where `groups` says, as MADD regions into out.regions
/// (in order of each group's representative face, which region_face gets), with their
/// features. Returns the joins that small angles between the regions ask for; out.regions is
/// left empty if there are any.
inline std::vector<face_join> regions_of_faces(const pslg& g, const domain_faces& faces,
                                               union_find& groups, face_region_set& out,
                                               std::vector<index_t>* region_face = nullptr) {
  const auto segs = segment_lookup(g);
  std::vector<domain_triangle> tris = faces.triangles();
  std::vector<char> in_domain(faces.face_count(), 0);
  for (domain_triangle& t : tris) {
    in_domain[t.face] = 1;
    t.face = groups.find(t.face);
  }
  out.faces = static_cast<std::size_t>(std::count(in_domain.begin(), in_domain.end(), 1));
  std::vector<std::vector<madd_feature>> features(faces.face_count());
  const std::vector<face_half_edge> edges = face_boundaries(g, tris, segs, features);
  add_isolated_vertices(g, tris, features);
  std::vector<face_half_edge> by_edge = edges;
  std::sort(by_edge.begin(), by_edge.end());
  std::vector<face_loops> loops_of;
  std::vector<face_join> joins = small_angle_joins(g, edges, by_edge, features, loops_of);
  if (!joins.empty()) return joins;
  for (const face_loops& f : loops_of) {
    out.regions.push_back(face_region(g, f.loops, segs));
    out.regions.back().features = std::move(features[f.face]);
    if (region_face) region_face->push_back(f.face);
  }
  return joins;
}

/// The regions of a capped domain (detail::cap_corners) into `out`, with tags and features
/// naming the input's segments (a chord: a separator edge) and the caps kept whole. Returns
/// the joins that small angles between regions still ask for (out.regions is then empty): a
/// corner of about 60 deg at the far end of a segment whose other end got a cap, measured
/// again from the cut point.
/// \throws pdd::decomposition_error if a cap's sector lies outside the domain (a bug).
inline std::vector<face_join> capped_regions(const capped_domain& capped, face_region_set& out) {
  const domain_faces faces(capped.g);
  union_find groups(faces.face_count());
  const auto face_at = [&](point p) {
    const face_location at = faces.locate(p);
    if (at.where != face_location::kind::inside)
      throw decomposition_error("MADD: a cap's sector at " + to_string(p) +
                                " lies outside the domain");
    return at.face;
  };
  std::vector<index_t> cap_face;
  for (const std::vector<point>& samples : capped.cap_samples) {
    cap_face.push_back(face_at(samples.front()));
    for (const point& p : samples)
      groups.unite(cap_face.back(), face_at(p));
  }
  std::vector<index_t> representative; // of each region's group, in region order
  std::vector<face_join> left = regions_of_faces(capped.g, faces, groups, out, &representative);
  if (!left.empty()) return left;
  for (const index_t f : cap_face) {
    const auto at = std::find(representative.begin(), representative.end(), groups.find(f));
    PDD_ASSERT(at != representative.end());
    out.regions[static_cast<std::size_t>(at - representative.begin())].keep_whole = true;
  }
  for (madd_region& r : out.regions) {
    for (madd_loop& l : r.loops)
      for (madd_edge_tag& tag : l.tags)
        if (capped.input_segment[tag.segment] == no_index)
          tag = madd_edge_tag{};
        else
          tag.segment = capped.input_segment[tag.segment];
    for (madd_feature& f : r.features)
      if (!f.is_vertex()) f.segment = capped.input_segment[f.segment];
  }
  return left;
}

/// Adds the vertices of `joins` that are vertices of g (ids below n) to `apexes` (sorted,
/// each once); returns how many were new.
inline std::size_t add_apexes(const std::vector<face_join>& joins, std::size_t n,
                              std::vector<index_t>& apexes) {
  const std::size_t before = apexes.size();
  for (const face_join& j : joins)
    if (j.vertex < n) apexes.push_back(j.vertex);
  std::sort(apexes.begin(), apexes.end());
  apexes.erase(std::unique(apexes.begin(), apexes.end()), apexes.end());
  return apexes.size() - before;
}

/// The faces of the domain of g (pdd::domain_faces by g.rule) as MADD regions with their
/// features (dangling segments, segments with the region on both sides, isolated vertices).
/// Each region's loops run along PSLG segments, tagged external with the segment id and
/// marker; a segment between two regions is an interface of the decomposition. Where a face's
/// corner below 60 deg lies on a segment between two faces, or a feature leaves a vertex at
/// below 60 deg to one, that vertex gets a cap (detail::cap_corners): a region kept whole, so
/// that no interface meets a small angle. `faces` are g's (pdd::domain_faces by g.rule, or
/// with validate_first for Triangle's). Complexity O(n log n) without caps, O(n (c + log n))
/// with c caps (once more when a cap's cut leaves a corner of about 60 deg below it).
/// \throws pdd::decomposition_error when the caps leave a small angle at a point they made (a
/// bug: their chords meet everything at >= 65 deg).
inline face_region_set face_regions(const pslg& g, const domain_faces& faces) {
  face_region_set out;
  union_find faces_alone(faces.face_count());
  const std::vector<face_join> joins = regions_of_faces(g, faces, faces_alone, out);
  if (joins.empty()) return out;
  const std::size_t face_count = out.faces;
  std::vector<index_t> apexes;
  add_apexes(joins, g.vertices.size(), apexes);
  for (;;) {
    const capped_domain capped = cap_corners(g, faces, apexes);
    out = {};
    const std::vector<face_join> left = capped_regions(capped, out);
    if (left.empty()) {
      out.faces = face_count;
      out.caps = capped.caps;
      out.cap_reason = caps_text(g, capped.caps.size(), joins.front().vertex);
      return out;
    }
    if (add_apexes(left, g.vertices.size(), apexes) == 0)
      throw decomposition_error("MADD: the caps left an angle below 60 deg at " +
                                to_string(capped.g.vertices[left.front().vertex]));
  }
}

/// face_regions on the faces of g by g.rule.
/// \throws pdd::geometry_error as pdd::domain_faces. Complexity O(n log n) expected.
inline face_region_set face_regions(const pslg& g) {
  return face_regions(g, domain_faces(g));
}

} // namespace pdd::detail
