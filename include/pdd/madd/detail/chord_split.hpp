/// \file chord_split.hpp
/// Implementation detail of MADD on a general PSLG (issue 13): the straight-chord split, tried
/// when the medial-axis split (split.hpp) finds no acceptable separator.
///
/// The MADD graph is built from the region's loops only; features inside the region
/// (dangling segments, wells, segments joining two boundary points) only forbid the candidate
/// separators near them (features.hpp). Where features fill the middle of a region, every
/// medial-axis separator passes near one and the region could not be split, although a
/// straight cut beside the features would do. This step looks for such a cut directly: a
/// chord between two refinement points of the outer loop (exact dyadic points, shared with the
/// neighbours as MADD's own separator ends are) that
///   - meets both loop edges at angles >= Phi0 on either side (in [Phi0, 180 - Phi0]),
///   - crosses and touches no loop edge but its two own (exact predicates),
///   - keeps at least the clearance max(h, feature_clearance) from every feature (as MADD's
///     separators do), every loop vertex and every other loop edge, so that it makes no local
///     feature size smaller than the level's spacing; and at least an eighth of the level-0
///     spacing, so that no sliver beside a feature makes k much smaller than the region needs.
/// Candidates are shot from every refinement point along the inward normal of its edge and at
/// +-15 and +-30 degrees from it, ended at the refinement point nearest to where the ray first
/// leaves the region. The most balanced chord wins (ties: the shorter), levels h, h/2, ... are
/// tried until one is balanced to the imbalance bound. The dissertation's MADD has no such
/// step: it decomposes domains without inner constraints. Its separators are straight, so the
/// decoupling path and the validation treat a chord as any other separator.
#pragma once

#include <pdd/madd/detail/features.hpp>
#include <pdd/madd/detail/region.hpp>
#include <pdd/madd/detail/split_result.hpp>
#include <pdd/madd/detail/triangulation.hpp>

#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace pdd::detail {

/// Where a ray from inside a region first meets its loops.
struct chord_ray_hit {
  std::uint32_t loop = 0, edge = 0;
  point at;
};

/// The first loop edge the ray p + s d (s > 0) meets, skipping `own_edge` of loop 0 (floating
/// point: it only proposes a candidate, which is then checked exactly).
inline std::optional<chord_ray_hit> cast_chord_ray(const madd_region& r, point p, point d,
                                                   std::uint32_t own_edge) {
  std::optional<chord_ray_hit> best;
  double best_s = std::numeric_limits<double>::infinity();
  for (std::uint32_t l = 0; l < r.loops.size(); ++l) {
    const madd_loop& lp = r.loops[l];
    for (std::uint32_t e = 0; e < lp.size(); ++e) {
      if (l == 0 && e == own_edge) continue;
      const point a = lp.points[e], b = lp.points[(e + 1) % lp.size()];
      const double ex = b.x - a.x, ey = b.y - a.y;
      const double den = d.x * ey - d.y * ex;
      if (den == 0.0) continue;
      const double s = ((a.x - p.x) * ey - (a.y - p.y) * ex) / den;
      const double t = ((a.x - p.x) * d.y - (a.y - p.y) * d.x) / den;
      if (!(s > 0.0) || t < 0.0 || t > 1.0 || !(s < best_s)) continue;
      best_s = s;
      best = chord_ray_hit{l, e, {p.x + s * d.x, p.y + s * d.y}};
    }
  }
  return best;
}

/// The refinement points (not region vertices) of each edge of the outer loop, as indices
/// into z, in loop order.
inline std::vector<std::vector<std::uint32_t>>
outer_edge_points(const madd_region& r, const std::vector<madd_zvertex>& z) {
  std::vector<std::vector<std::uint32_t>> out(r.loops[0].size());
  for (std::uint32_t i = 0; i < z.size(); ++i)
    if (z[i].loop == 0 && !z[i].original) out[z[i].edge].push_back(i);
  return out;
}

/// The refinement point of `pts` nearest to x (the first of equals); no_index if none.
inline std::uint32_t nearest_point(const std::vector<madd_zvertex>& z,
                                   const std::vector<std::uint32_t>& pts, point x) {
  std::uint32_t best = no_index;
  double best_d = std::numeric_limits<double>::infinity();
  for (const std::uint32_t i : pts)
    if (const double dd = distance(z[i].p, x); dd < best_d) {
      best_d = dd;
      best = i;
    }
  return best;
}

/// True when the chord from u meets u's edge at angles in [phi0, 180 - phi0] and leaves it
/// into the region (strictly left of the edge; exact orientation).
inline bool chord_end_ok(const madd_zvertex& u, point other, double phi0) {
  const double a = angle_deg(u.p, other, u.far_next);
  if (a < phi0 || 180.0 - a < phi0) return false;
  const epick::Point_2 pa(u.far_prev.x, u.far_prev.y), pb(u.far_next.x, u.far_next.y);
  return CGAL::orientation(pa, pb, epick::Point_2(other.x, other.y)) == CGAL::LEFT_TURN;
}

/// True when the chord u w crosses or touches no loop edge but u's and w's own (exact), and
/// keeps `clearance` from every loop vertex and from every other loop edge.
inline bool chord_clear_of_loops(const madd_region& r, const madd_zvertex& u, const madd_zvertex& w,
                                 double clearance) {
  const epick::Segment_2 chord(epick::Point_2(u.p.x, u.p.y), epick::Point_2(w.p.x, w.p.y));
  for (std::uint32_t l = 0; l < r.loops.size(); ++l) {
    const madd_loop& lp = r.loops[l];
    for (std::uint32_t e = 0; e < lp.size(); ++e) {
      const point a = lp.points[e], b = lp.points[(e + 1) % lp.size()];
      if (point_segment_distance(a, u.p, w.p) < clearance) return false;
      if (l == 0 && (e == u.edge || e == w.edge)) continue;
      if (CGAL::do_intersect(chord,
                             epick::Segment_2(epick::Point_2(a.x, a.y), epick::Point_2(b.x, b.y))))
        return false;
      if (std::min(point_segment_distance(u.p, a, b), point_segment_distance(w.p, a, b)) <
          clearance)
        return false;
    }
  }
  return true;
}

/// True when the chord keeps `clearance` from every feature of r (and touches none).
inline bool chord_clear_of_features(const madd_region& r, point p, point q, double clearance) {
  for (const madd_feature& f : r.features)
    if (near_feature(p, q, f, clearance)) return false;
  return true;
}

/// The outer-loop part from u (on edge i) forwards to w (on edge j), closed by the chord w -> u:
/// u, points[i + 1], ..., points[j], w, with the loop's markers and tags.
inline madd_loop chord_side(const madd_loop& outer, const madd_zvertex& u, const madd_zvertex& w) {
  madd_loop side;
  const std::size_t n = outer.size();
  side.points.push_back(u.p);
  side.markers.push_back(u.marker);
  side.tags.push_back(outer.tags[u.edge]);
  for (std::size_t e = (u.edge + 1) % n;; e = (e + 1) % n) {
    side.points.push_back(outer.points[e]);
    side.markers.push_back(outer.markers[e]);
    side.tags.push_back(outer.tags[e]);
    if (e == w.edge) break;
  }
  side.points.push_back(w.p);
  side.markers.push_back(w.marker);
  side.tags.push_back(madd_edge_tag{}); // the chord: a separator
  return side;
}

/// The two children of r cut by the chord u w, without features: outer loops from
/// chord_side, each hole in the child whose outer loop holds it, and their areas.
inline std::array<madd_region, 2> chord_cut(const madd_region& r, const madd_zvertex& u,
                                            const madd_zvertex& w) {
  std::array<madd_region, 2> ch;
  ch[0].loops.push_back(chord_side(r.loops[0], u, w));
  ch[1].loops.push_back(chord_side(r.loops[0], w, u));
  const std::vector<epick::Point_2> first = cgal_loop(ch[0].loops[0]);
  for (std::size_t l = 1; l < r.loops.size(); ++l) {
    // the side of the hole's first vertex off the first child's outer loop (a hole may touch
    // the outer loop at a pinch vertex; the chord keeps its clearance from every vertex)
    CGAL::Bounded_side side = CGAL::ON_BOUNDARY;
    for (std::size_t i = 0; i < r.loops[l].size() && side == CGAL::ON_BOUNDARY; ++i) {
      const point p = r.loops[l].points[i];
      side = CGAL::bounded_side_2(first.begin(), first.end(), epick::Point_2(p.x, p.y), epick());
    }
    ch[side == CGAL::ON_BOUNDED_SIDE ? 0 : 1].loops.push_back(r.loops[l]);
  }
  for (madd_region& c : ch)
    c.area = region_area(c);
  return ch;
}

/// The best chord found so far.
struct chord_choice {
  std::uint32_t u = no_index, w = no_index;
  double fraction = 2.0, length = 0.0;
  bool better_than(const chord_choice& o) const {
    return fraction < o.fraction || (fraction == o.fraction && length < o.length);
  }
};

/// The split_balance of r cut by the chord u w into `quota` subdomains (for quota 2, the
/// larger child's share of the area).
inline double chord_fraction(const madd_region& r, const madd_zvertex& u, const madd_zvertex& w,
                             std::size_t quota) {
  const std::array<madd_region, 2> ch = chord_cut(r, u, w);
  return split_balance(ch[0].area, ch[1].area, quota);
}

/// The chord from refinement point u along direction d, checked; nullopt when it fails.
inline std::optional<chord_choice>
chord_from(const madd_region& r, const std::vector<madd_zvertex>& z,
           const std::vector<std::vector<std::uint32_t>>& edge_pts, std::uint32_t u, point d,
           double phi0, double clearance, std::size_t quota) {
  const std::optional<chord_ray_hit> hit = cast_chord_ray(r, z[u].p, d, z[u].edge);
  if (!hit || hit->loop != 0) return std::nullopt;
  const std::uint32_t w = nearest_point(z, edge_pts[hit->edge], hit->at);
  if (w == no_index) return std::nullopt;
  if (!chord_end_ok(z[u], z[w].p, phi0) || !chord_end_ok(z[w], z[u].p, phi0)) return std::nullopt;
  if (!chord_clear_of_loops(r, z[u], z[w], clearance)) return std::nullopt;
  if (!chord_clear_of_features(r, z[u].p, z[w].p, clearance)) return std::nullopt;
  return chord_choice{u, w, chord_fraction(r, z[u], z[w], quota), distance(z[u].p, z[w].p)};
}

/// The least clearance of a chord, as a share of the region's level-0 spacing (the split's
/// target_length): a sliver beside a feature would make k, and so the mesh, much finer than
/// the region needs (MADD's medial-axis separators keep their distance by running along the
/// medial axis).
inline constexpr double min_chord_clearance = 0.125;

/// The most starts best_chord_at shoots rays from.
inline constexpr std::size_t max_chord_starts = 512;

/// The best chord of r at spacing h (Z of build_z), or u == no_index: rays from the
/// refinement points of the outer loop (every stride-th where there are more than
/// max_chord_starts).
inline chord_choice best_chord_at(const madd_region& r, const std::vector<madd_zvertex>& z,
                                  double phi0, double clearance, std::size_t quota) {
  const std::vector<std::vector<std::uint32_t>> edge_pts = outer_edge_points(r, z);
  std::vector<std::uint32_t> starts;
  for (const std::vector<std::uint32_t>& pts : edge_pts)
    starts.insert(starts.end(), pts.begin(), pts.end());
  // at most about max_chord_starts rays' starts, evenly spread (the cost is starts * edges)
  const std::size_t stride = 1 + starts.size() / max_chord_starts;
  chord_choice best;
  for (std::size_t k = 0; k < starts.size(); k += stride) {
    const std::uint32_t u = starts[k];
    const double ex = z[u].far_next.x - z[u].far_prev.x, ey = z[u].far_next.y - z[u].far_prev.y;
    const double base = std::atan2(ex, -ey); // the inward (left) normal of the edge
    for (const double turn : {0.0, 15.0, -15.0, 30.0, -30.0}) {
      const double a = base + turn * (std::numbers::pi / 180.0);
      const std::optional<chord_choice> c =
          chord_from(r, z, edge_pts, u, {std::cos(a), std::sin(a)}, phi0, clearance, quota);
      if (c && c->better_than(best)) best = *c;
    }
  }
  return best;
}

/// The straight-chord split of r (see the file comment), levels target_length * 2^-level for
/// level < max_levels; ok is false, with failure set, when no level has a chord.
inline madd_split_result chord_split(const madd_region& r, const madd_split_options& o) {
  madd_split_result best;
  chord_choice best_choice;
  std::vector<madd_zvertex> best_z;
  for (int level = 0; level < o.max_levels; ++level) {
    const double h = std::ldexp(o.target_length, -level);
    if (z_point_count(r, h) > max_z_points) break; // finer levels need even more
    std::vector<madd_zvertex> z;
    build_z(r, h, z);
    ++best.levels_tried;
    const double clearance =
        std::max({h, o.feature_clearance, min_chord_clearance * o.target_length});
    const chord_choice c = best_chord_at(r, z, o.graph.phi0_accept, clearance, o.quota);
    if (c.u == no_index || !c.better_than(best_choice)) continue;
    best_choice = c;
    best_z = std::move(z);
    best.level = level;
    best.z_points = best_z.size();
    if (c.fraction <= o.imbalance_bound) break;
  }
  if (best_choice.u == no_index) {
    best.failure = "no straight chord clear of the features either";
    return best;
  }
  const madd_zvertex& u = best_z[best_choice.u];
  const madd_zvertex& w = best_z[best_choice.w];
  best.children = chord_cut(r, u, w);
  distribute_features(r, best.children);
  for (const madd_zvertex* x : {&u, &w}) {
    const point a = x->far_prev, b = x->far_next;
    best.kept.push_back({std::min(a, b), std::max(a, b), x->t, x->p, x->marker});
  }
  best.ok = true;
  best.chord = true;
  best.separator_length = best_choice.length;
  best.max_fraction = best_choice.fraction;
  best.min_angle =
      std::min({angle_deg(u.p, w.p, u.far_next), 180.0 - angle_deg(u.p, w.p, u.far_next),
                angle_deg(w.p, u.p, w.far_next), 180.0 - angle_deg(w.p, u.p, w.far_next)});
  return best;
}

} // namespace pdd::detail
