/// \file features.hpp
/// Implementation detail of MADD on a general PSLG (issue 13): keeping separators away from the
/// features of a region (madd_feature: dangling segments, segments with the region on both
/// sides, isolated vertices), and handing each feature to the child that holds it.
///
/// A candidate separator piece (a cell face of the MADD graph: a Delaunay edge between two
/// boundary points, or a segment from a boundary point to a junction triangle's circumcentre)
/// that comes closer than the level's spacing h to a feature, or touches it (decided exactly),
/// becomes uncuttable before the bisection. So no separator crosses or touches a feature, and
/// the lfs_min that k is taken from (pdd::decouple, with the features in each subdomain's
/// input) is not made smaller than h by a separator passing a feature. Every feature then lies
/// in the interior of one child (its ends may lie on the region's loops, never on a
/// separator), found by an exact point-in-polygon test.
#pragma once

#include <pdd/core/kernel.hpp>
#include <pdd/madd/detail/graph.hpp>
#include <pdd/madd/detail/region.hpp>
#include <pdd/madd/detail/triangulation.hpp>

#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace pdd::detail {

/// Distance from p to the segment ab (floating point).
inline double point_segment_distance(point p, point a, point b) noexcept {
  const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  double t = len2 > 0.0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

/// True when the segment pq touches the feature f (exact) or passes within `clearance` of it.
inline bool near_feature(point p, point q, const madd_feature& f, double clearance) {
  const epick::Point_2 cp(p.x, p.y), cq(q.x, q.y), ca(f.a.x, f.a.y);
  if (f.is_vertex())
    return CGAL::do_intersect(epick::Segment_2(cp, cq), ca) ||
           point_segment_distance(f.a, p, q) < clearance;
  const epick::Point_2 cb(f.b.x, f.b.y);
  if (CGAL::do_intersect(epick::Segment_2(cp, cq), epick::Segment_2(ca, cb))) return true;
  return std::min({point_segment_distance(f.a, p, q), point_segment_distance(f.b, p, q),
                   point_segment_distance(p, f.a, f.b), point_segment_distance(q, f.a, f.b)}) <
         clearance;
}

/// The axis-aligned box of the features, grown by `margin`.
struct feature_box {
  double x0 = 0.0, y0 = 0.0, x1 = -1.0, y1 = -1.0;
  bool meets(point p, point q) const noexcept {
    return std::max(p.x, q.x) >= x0 && std::min(p.x, q.x) <= x1 && std::max(p.y, q.y) >= y0 &&
           std::min(p.y, q.y) <= y1;
  }
};

inline feature_box features_box(const std::vector<madd_feature>& fs, double margin) {
  feature_box b{fs[0].a.x, fs[0].a.y, fs[0].a.x, fs[0].a.y};
  for (const madd_feature& f : fs)
    for (const point p : {f.a, f.b}) {
      b.x0 = std::min(b.x0, p.x);
      b.y0 = std::min(b.y0, p.y);
      b.x1 = std::max(b.x1, p.x);
      b.y1 = std::max(b.y1, p.y);
    }
  b.x0 -= margin;
  b.y0 -= margin;
  b.x1 += margin;
  b.y1 += margin;
  return b;
}

/// Makes every cuttable cell face of g that comes within `clearance` of a feature of r (or
/// touches one) uncuttable, and contracts g again. Returns the number of faces made uncuttable.
/// Complexity O(faces near the features' box * features).
inline std::size_t forbid_cuts_near_features(const madd_region& r, const madd_triangulation& tr,
                                             madd_graph& g, double clearance) {
  if (r.features.empty()) return 0;
  const feature_box box = features_box(r.features, clearance);
  std::size_t forbidden = 0;
  for (madd_cell_face& f : g.faces) {
    if (!f.cuttable) continue;
    const point p = tr.z[f.z0].p;
    const point q = f.z1 != no_index ? tr.z[f.z1].p : g.info[f.tri].c;
    if (!box.meets(p, q)) continue;
    for (const madd_feature& ft : r.features)
      if (near_feature(p, q, ft, clearance)) {
        f.cuttable = false;
        ++forbidden;
        break;
      }
  }
  if (forbidden > 0) contract(g);
  return forbidden;
}

/// A loop as CGAL points (for the exact point-in-polygon test).
inline std::vector<epick::Point_2> cgal_loop(const madd_loop& l) {
  std::vector<epick::Point_2> out;
  out.reserve(l.size());
  for (const point& p : l.points)
    out.emplace_back(p.x, p.y);
  return out;
}

/// True when p lies inside the region (inside its outer loop and outside its holes; exact).
/// p must not lie on the region's loops.
inline bool region_holds(const std::vector<std::vector<epick::Point_2>>& loops, point p) {
  const epick::Point_2 q(p.x, p.y);
  for (std::size_t l = 0; l < loops.size(); ++l) {
    const CGAL::Bounded_side side =
        CGAL::bounded_side_2(loops[l].begin(), loops[l].end(), q, epick());
    if ((l == 0) != (side == CGAL::ON_BOUNDED_SIDE)) return false;
  }
  return true;
}

/// A point of the feature in its interior (never on a separator, nor on the region's loops):
/// the vertex, or the midpoint of the segment.
inline point feature_probe(const madd_feature& f) noexcept {
  return f.is_vertex() ? f.a : canonical_midpoint(f.a, f.b);
}

/// Hands every feature of the parent to the child that holds it (child 1 when child 0 does
/// not). \pre no separator touches a feature (forbid_cuts_near_features).
inline void distribute_features(const madd_region& parent, std::array<madd_region, 2>& children) {
  if (parent.features.empty()) return;
  std::vector<std::vector<epick::Point_2>> first;
  for (const madd_loop& l : children[0].loops)
    first.push_back(cgal_loop(l));
  for (const madd_feature& f : parent.features)
    children[region_holds(first, feature_probe(f)) ? 0 : 1].features.push_back(f);
}

} // namespace pdd::detail
