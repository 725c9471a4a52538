/// \file shield_decomposition.hpp
/// pdd::shield_decomposition: Algorithm 8.2 of the dissertation on a decomposition: every
/// subdomain with external boundary angles < 60 deg is shielded independently (in parallel).
#pragma once

#include <pdd/concepts/executor.hpp>
#include <pdd/core/triangle_measures.hpp>
#include <pdd/errors.hpp>
#include <pdd/geometry/lfs.hpp>
#include <pdd/madd/decomposition.hpp>
#include <pdd/madd/subdomain_pslg.hpp>
#include <pdd/parallel/sequential_executor.hpp>
#include <pdd/shielding/detail/plan.hpp>
#include <pdd/shielding/shield_triangle.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace pdd {

/// The shielding of one subdomain (see shield_decomposition).
struct subdomain_shields {
  std::vector<shield_triangle> triangles;                   ///< T(D_i); vertex ids are pool ids
  double l = std::numeric_limits<double>::infinity();       ///< l_i (Algorithm 8.2 line 5)
  double lfs_min = std::numeric_limits<double>::infinity(); ///< lfs_min(D_i) before shielding
};

/// The cap on l_i for a decomposition whose unshielded decoupling parameter is k0:
/// sqrt 3 k0, less one part in 1e9 for rounding (see shield_decomposition). Complexity O(1).
inline double shield_length_cap(double k0) {
  return std::sqrt(3.0) * k0 * (1.0 - 1e-9);
}

/// Shields the small angles of every subdomain of d in place (Algorithm 8.2 with the uniform
/// area bound m(D_i) = area_bound): l_i = min over its angles theta < 60 deg of
/// {(1 + 2 sin(theta/2)) sqrt(2 A sin theta), sqrt(A / sqrt 2), lfs_min(D_i)}, the shield
/// points b', c' at eq. 8.1 are appended to the vertex pool (marker: their segment's), and the
/// apex a is replaced in its loop by b', c' with the shield edge b' -> c' tagged external with
/// pdd::shield_marker (id no_index). Subdomain areas drop by the shielded triangles' areas.
/// Subdomains without small angles are unchanged, so a decomposition without any is unchanged.
/// The shielded loops are what pdd::decouple then sees: its k uses lfs_min(D_i') (Theorem 24
/// (3): > l_i / sqrt 3).
/// `max_l` caps every l_i. With a decoupling path it must be at most sqrt 3 k0, k0 the
/// decoupling parameter of the unshielded decomposition (pdd::pipeline passes
/// shield_length_cap(k0)): the separators are split into pieces shorter than 2k, which makes
/// every subdomain's features as small as k, and a shield edge is then safe from splitting like
/// an interface piece only when it is shorter than 2k. With l_i <= sqrt 3 k0 and
/// k = min(k0, lfs_min(D_i')): |b'c'| = l_i / (cos(theta/2) + sin theta) <= l_i < 2 k0, and,
/// when lfs_min(D_i') is the smaller, lfs_min(D_i') > l_i / 2 (Lemma 23 (iii) gives l_i / sqrt 3
/// for theta <= 30 deg; tests/shielding measures > l_i / 2 up to 59 deg) while
/// |b'c'| < l_i since cos(theta/2) + sin theta > 1. The cap sqrt 3 k0 (rather than k0) keeps
/// lfs_min(D_i') >= k0, so k = k0 and the shields do not shorten the interface pieces
/// (measured from 10 to 59 deg in tests/shielding; with the cap k0, k fell to 0.58-0.85 k0).
/// Below about 7 deg the area term of l_i is itself shorter than sqrt 3 k0 and k falls with it.
/// (Theorem 24 (5) assumes |b'c'| < 2 lfs_min(D_i) suffices; in a thin tip subdomain meshed
/// with a global k << lfs_min(D_i), CGAL splits such a shield edge.)
/// \returns per subdomain its shielded triangles (empty for most).
/// \pre d as MADD makes it: outer loop counter-clockwise, holes clockwise.
/// \throws pdd::decomposition_error when a small angle has a separator as one of its sides
/// (MADD's angle criterion C1 with Phi0 >= 60 deg excludes it); pdd::geometry_error as
/// pdd::shield. Complexity: lfs_min of every subdomain with small angles, in parallel, plus
/// linear work. The result is the same for every executor.
template <Executor E = sequential_executor>
std::vector<subdomain_shields>
shield_decomposition(decomposition& d, double area_bound, const E& executor = {},
                     double max_l = std::numeric_limits<double>::infinity()) {
  const std::size_t m = d.subdomains.size();
  std::vector<subdomain_shields> out(m);
  // Per subdomain, per loop: the angles (0: not shielded) and the distances |ab'|.
  std::vector<std::vector<std::vector<double>>> theta(m), dist(m);
  std::vector<double> work(m);
  for (std::size_t s = 0; s < m; ++s)
    for (const auto& loop : d.subdomains[s].loops)
      work[s] += static_cast<double>(loop.size());
  // The executor rethrows the original exception of the smallest failing subdomain.
  executor.run(work, [&](index_t s) {
    const subdomain& sd = d.subdomains[s];
    bool any = false;
    for (std::size_t l = 0; l < sd.loops.size(); ++l) {
      const auto& loop = sd.loops[l];
      const std::size_t n = loop.size();
      std::vector<point> pts;
      for (const index_t v : loop)
        pts.push_back(d.vertices[v]);
      theta[s].push_back(detail::shield_angles(pts, std::vector<char>(n, 1)));
      for (std::size_t i = 0; i < n; ++i) {
        if (theta[s][l][i] == 0.0) continue;
        any = true;
        if (sd.tags[l][i].type != edge_tag::kind::external ||
            sd.tags[l][(i + n - 1) % n].type != edge_tag::kind::external)
          throw decomposition_error("subdomain " + std::to_string(s) + ": the angle of " +
                                    std::to_string(theta[s][l][i]) + " deg at vertex " +
                                    std::to_string(loop[i]) +
                                    " is formed by a separator; it cannot be shielded");
      }
    }
    if (!any) return;
    pslg g;
    std::vector<index_t> unused;
    detail::build_subdomain_pslg(
        d, s, g, [](std::size_t, index_t, index_t, pslg&) { return no_index; }, unused,
        interface_marker);
    out[s].lfs_min = lfs_min(g);
    out[s].l = std::min(max_l, detail::shield_length(theta[s], out[s].lfs_min, area_bound));
    for (std::size_t l = 0; l < sd.loops.size(); ++l) {
      std::vector<point> pts;
      for (const index_t v : sd.loops[l])
        pts.push_back(d.vertices[v]);
      dist[s].push_back(detail::shield_distances(pts, theta[s][l], out[s].l, sd.loops[l]));
    }
  });
  // Sequentially, in subdomain order: the pool grows deterministically.
  const bool markers = !d.vertex_markers.empty();
  for (std::size_t s = 0; s < m; ++s) {
    if (dist[s].empty()) continue;
    subdomain& sd = d.subdomains[s];
    for (std::size_t l = 0; l < sd.loops.size(); ++l) {
      const std::vector<index_t> loop = sd.loops[l];
      const std::vector<edge_tag> tags = sd.tags[l];
      const std::size_t n = loop.size();
      std::vector<index_t> nl;
      std::vector<edge_tag> nt;
      for (std::size_t i = 0; i < n; ++i) {
        const double di = dist[s][l][i];
        if (di == 0.0) {
          nl.push_back(loop[i]);
          nt.push_back(tags[i]);
          continue;
        }
        const point a = d.vertices[loop[i]];
        const edge_tag& in_tag = tags[(i + n - 1) % n];
        const point pb = detail::shield_point(a, d.vertices[loop[(i + n - 1) % n]], di);
        const point nb = detail::shield_point(a, d.vertices[loop[(i + 1) % n]], di);
        const auto ip = static_cast<index_t>(d.vertices.size());
        d.vertices.push_back(pb);
        d.vertices.push_back(nb);
        if (markers) {
          d.vertex_markers.push_back(in_tag.marker);
          d.vertex_markers.push_back(tags[i].marker);
        }
        nl.push_back(ip);
        nt.push_back({edge_tag::kind::external, no_index, shield_marker, no_index});
        nl.push_back(ip + 1);
        nt.push_back(tags[i]);
        shield_triangle t;
        t.apex = a;
        t.apex_marker = markers ? d.vertex_markers[loop[i]] : 0;
        t.b = nb;
        t.c = pb;
        t.marker_ab = tags[i].marker;
        t.marker_ac = in_tag.marker;
        t.angle_deg = theta[s][l][i];
        t.apex_vertex = loop[i];
        t.b_vertex = ip + 1;
        t.c_vertex = ip;
        if (sd.area > 0.0) sd.area -= detail::triangle_area(a, nb, pb);
        out[s].triangles.push_back(t);
      }
      sd.loops[l] = std::move(nl);
      sd.tags[l] = std::move(nt);
    }
  }
  return out;
}

} // namespace pdd

namespace pdd::detail {
/// True when some subdomain of d has a domain-side angle < 60 deg (loops are walked with the
/// domain on their left). Complexity O(size of d).
inline bool has_small_angles(const decomposition& d) {
  for (const subdomain& sd : d.subdomains)
    for (const auto& loop : sd.loops) {
      const std::size_t n = loop.size();
      for (std::size_t i = 0; i < n; ++i)
        if (ccw_angle_deg(d.vertices[loop[i]], d.vertices[loop[(i + 1) % n]],
                          d.vertices[loop[(i + n - 1) % n]]) < shield_threshold_deg)
          return true;
    }
  return false;
}
} // namespace pdd::detail
