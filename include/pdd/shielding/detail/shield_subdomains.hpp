/// \file shield_subdomains.hpp
/// Implementation of pdd::shield_subdomains (shielding/subdomain_shields.hpp): the small angles
/// of one subdomain of a decomposition, and the shield points and triangles placed into it
/// (Algorithm 8.2, steps 5-12).
#pragma once

#include <pdd/core/decomposition.hpp>
#include <pdd/core/triangle_measures.hpp>
#include <pdd/errors.hpp>
#include <pdd/shielding/detail/plan.hpp>
#include <pdd/shielding/shield_triangle.hpp>

#include <algorithm>
#include <string>
#include <vector>

namespace pdd::detail {

/// The points of one loop of the decomposition's vertex pool.
inline std::vector<point> loop_points(const decomposition& d, const std::vector<index_t>& loop) {
  std::vector<point> pts;
  pts.reserve(loop.size());
  for (const index_t v : loop)
    pts.push_back(d.vertices[v]);
  return pts;
}

/// The pool ids where an inner constraint of subdomain s ends (sorted): a segment inside the
/// subdomain that starts at a corner of its loops.
inline std::vector<index_t> inner_constraint_ends(const subdomain& sd) {
  std::vector<index_t> ends;
  for (const inner_constraint& c : sd.inner) {
    ends.push_back(c.a);
    ends.push_back(c.b);
  }
  std::sort(ends.begin(), ends.end());
  return ends;
}

/// Per loop of subdomain s: its domain-side angles < 60 deg (0 elsewhere, see shield_angles).
/// A corner where an inner constraint of the subdomain starts (a segment from its apex into
/// the subdomain) is not shielded either: a shield triangle would cross that segment. The
/// corner and the segment then form sectors below 60 deg inside the subdomain, which its
/// kernel meshes as it meshes any small angle between constraints (CGAL's clusters, the native
/// kernel's concentric shells; the exempt triangles are pdd::find_cluster_exempt_triangles').
/// Both sides of the corner are external edges of this subdomain only, so the splits the
/// kernel makes there stay inside it.
/// \throws pdd::decomposition_error when a small angle has a separator as one of its sides
/// (MADD's angle criterion C1 with Phi0 >= 60 deg excludes it).
inline std::vector<std::vector<double>> subdomain_small_angles(const decomposition& d,
                                                               std::size_t s) {
  const subdomain& sd = d.subdomains[s];
  const std::vector<index_t> inner_ends = inner_constraint_ends(sd);
  std::vector<std::vector<double>> theta;
  for (std::size_t l = 0; l < sd.loops.size(); ++l) {
    const auto& loop = sd.loops[l];
    const std::size_t n = loop.size();
    theta.push_back(shield_angles(loop_points(d, loop), std::vector<char>(n, 1)));
    for (std::size_t i = 0; i < n; ++i)
      if (theta[l][i] != 0.0 && (sd.tags[l][i].type != edge_tag::kind::external ||
                                 sd.tags[l][(i + n - 1) % n].type != edge_tag::kind::external))
        throw decomposition_error("subdomain " + std::to_string(s) + ": the angle of " +
                                  std::to_string(theta[l][i]) + " deg at vertex " +
                                  std::to_string(loop[i]) +
                                  " is formed by a separator; it cannot be shielded");
    for (std::size_t i = 0; i < n; ++i)
      if (std::binary_search(inner_ends.begin(), inner_ends.end(), loop[i])) theta[l][i] = 0.0;
  }
  return theta;
}

/// True when some angle of `theta` is shielded (> 0).
inline bool any_small_angle(const std::vector<std::vector<double>>& theta) {
  for (const auto& loop : theta)
    for (const double t : loop)
      if (t > 0.0) return true;
  return false;
}

/// Replaces the apex loop[i] of loop l of subdomain s (|ab'| = dist, angle theta) by its shield
/// points b', c' (appended to the pool, markers of their segments) and the shield edge
/// c' -> b' (external, pdd::shield_marker) in nl / nt; returns the shielded triangle.
inline shield_triangle place_shield(decomposition& d, std::size_t s, std::size_t l, std::size_t i,
                                    double dist, double theta, std::vector<index_t>& nl,
                                    std::vector<edge_tag>& nt) {
  const std::vector<index_t>& loop = d.subdomains[s].loops[l];
  const std::vector<edge_tag>& tags = d.subdomains[s].tags[l];
  const std::size_t n = loop.size();
  const bool markers = !d.vertex_markers.empty();
  const point a = d.vertices[loop[i]];
  const edge_tag in_tag = tags[(i + n - 1) % n], out_tag = tags[i];
  const point pb = shield_point(a, d.vertices[loop[(i + n - 1) % n]], dist);
  const point nb = shield_point(a, d.vertices[loop[(i + 1) % n]], dist);
  const auto ip = static_cast<index_t>(d.vertices.size());
  shield_triangle t;
  t.apex = a;
  t.apex_marker = markers ? d.vertex_markers[loop[i]] : 0;
  t.b = nb;
  t.c = pb;
  t.marker_ab = out_tag.marker;
  t.marker_ac = in_tag.marker;
  t.angle_deg = theta;
  t.apex_vertex = loop[i];
  t.b_vertex = ip + 1;
  t.c_vertex = ip;
  d.vertices.push_back(pb);
  d.vertices.push_back(nb);
  if (markers) {
    d.vertex_markers.push_back(in_tag.marker);
    d.vertex_markers.push_back(out_tag.marker);
  }
  nl.push_back(ip);
  nt.push_back({edge_tag::kind::external, no_index, shield_marker, no_index});
  nl.push_back(ip + 1);
  nt.push_back(out_tag);
  return t;
}

/// Shields subdomain s of d in place with the distances dist[l][i] (0: not shielded) and the
/// angles theta[l][i]: every shielded apex is replaced by its shield points and edge, the
/// subdomain's area drops by the triangles' areas. Returns the shielded triangles.
inline std::vector<shield_triangle>
place_subdomain_shields(decomposition& d, std::size_t s,
                        const std::vector<std::vector<double>>& dist,
                        const std::vector<std::vector<double>>& theta) {
  std::vector<shield_triangle> out;
  for (std::size_t l = 0; l < d.subdomains[s].loops.size(); ++l) {
    const std::size_t n = d.subdomains[s].loops[l].size();
    std::vector<index_t> nl;
    std::vector<edge_tag> nt;
    for (std::size_t i = 0; i < n; ++i) {
      if (dist[l][i] == 0.0) {
        nl.push_back(d.subdomains[s].loops[l][i]);
        nt.push_back(d.subdomains[s].tags[l][i]);
        continue;
      }
      out.push_back(place_shield(d, s, l, i, dist[l][i], theta[l][i], nl, nt));
      subdomain& sd = d.subdomains[s];
      if (sd.area > 0.0) sd.area -= triangle_area(out.back().apex, out.back().b, out.back().c);
    }
    d.subdomains[s].loops[l] = std::move(nl);
    d.subdomains[s].tags[l] = std::move(nt);
  }
  return out;
}

} // namespace pdd::detail
