/// \file domain_region.hpp
/// pdd::triangulated_region: a domain's or subdomain's faces as triangles, the region over
/// which pdd::sizing_range bounds a field (holes and outside left out).
#pragma once

#include <pdd/core/index.hpp>
#include <pdd/core/point.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/geometry/domain_faces.hpp>
#include <pdd/sizing/sizing_region.hpp>

#include <array>
#include <span>
#include <utility>
#include <vector>

namespace pdd {

/// A region that owns its vertices and triangles; view() is the pdd::sizing_region of them.
struct triangulated_region {
  std::vector<point> vertices;                   ///< the points the triangles index
  std::vector<std::array<index_t, 3>> triangles; ///< the region's triangles
  /// The region as pdd::sizing_range takes it (valid while this object lives).
  sizing_region view() const { return {vertices, triangles}; }
};

/// The region of the triangles `triangles` (pdd::domain_faces::triangles()) over `vertices`.
inline triangulated_region domain_region(std::vector<point> vertices,
                                         std::span<const domain_triangle> triangles) {
  triangulated_region r;
  r.vertices = std::move(vertices);
  r.triangles.reserve(triangles.size());
  for (const domain_triangle& t : triangles)
    r.triangles.push_back(t.vertices);
  return r;
}

/// The region of domain g: its faces by g.rule (pdd::domain_faces, one constrained Delaunay
/// triangulation). \throws pdd::geometry_error as pdd::domain_faces.
inline triangulated_region domain_region(const pslg& g) {
  return domain_region(g.vertices, domain_faces(g).triangles());
}

/// The region bounded by closed loops of points (odd nesting: loops[0] the outer boundary of
/// a subdomain, the others its holes, as MADD's leaves and subdomains give them).
/// \throws pdd::geometry_error as pdd::domain_faces.
/// \tparam Loops a range of ranges of pdd::point.
template <class Loops>
triangulated_region loops_region(const Loops& loops) {
  pslg g;
  for (const auto& loop : loops)
    g.add_loop(loop);
  return domain_region(g);
}

} // namespace pdd
