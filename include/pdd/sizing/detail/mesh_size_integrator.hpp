/// \file detail/mesh_size_integrator.hpp
/// Implementation of pdd/sizing/mesh_size_estimate.hpp: the adaptive integral of
/// 1 / min(F, c gap^2) over the triangles of a feature_gap_field, with the features that add
/// the most triangles.
#pragma once

#include <pdd/concepts/sizing_field.hpp>
#include <pdd/core/point.hpp>
#include <pdd/geometry/feature_gap.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <map>
#include <numbers>
#include <tuple>

namespace pdd::detail {

/// What one feature pair adds to the integral, and where its bound is tightest.
struct feature_excess {
  double integral = 0.0;                                     ///< added to the integral of 1/F
  double tightest = std::numeric_limits<double>::infinity(); ///< min c gap^2 / F seen
  point where;                                               ///< the centroid there
  double gap = 0.0, bound = 0.0;                             ///< its gap and F there
  feature_pair pair;
};

/// The adaptive integration (see pdd::estimate_mesh_size).
template <SizingField S>
class mesh_size_integrator {
public:
  using key = std::tuple<int, index_t, int, index_t>;
  static constexpr int max_depth = 120;
  static constexpr std::size_t piece_budget = std::size_t{1} << 20;
  static constexpr double even_variation = 2.0; ///< gap max / min accepted without splitting

  mesh_size_integrator(const feature_gap_field& field, double max_area, const S& sizing,
                       double gap_area_factor, double across_area_factor, double shield_area)
      : field_(field), max_area_(max_area), sizing_(sizing), c_(gap_area_factor),
        c_across_(across_area_factor), shield_area_(shield_area), lfs_min_(field.min_vertex_gap()) {
  }

  /// A corner of a piece with its gap sample (shared by the pieces that meet there).
  struct corner {
    point p;
    gap_sample gap;
  };

  /// Integrates over triangle t of the field (the top-level pieces of one n x n subdivision).
  /// A piece where F is below a quarter of the smallest feature bound sampled on its input
  /// triangle (corners, edge midpoints, centroid) counts by F alone without sampling the gap:
  /// with a sizing field's n x n subdivision most pieces are such.
  double top(std::size_t t, const point& a, const point& b, const point& c) {
    if (t != bounded_triangle_) {
      bounded_triangle_ = t;
      triangle_bound_ = triangle_bound(t);
    }
    const point x{(a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0};
    const double f = std::min(max_area_, static_cast<double>(sizing_.area_at(x)));
    if (4.0 * f < triangle_bound_) {
      const double by_area =
          std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)) / 2.0 / f;
      area_integral += by_area;
      ++pieces_;
      return by_area;
    }
    return piece(t, {a, field_.at(a, t)}, {b, field_.at(b, t)}, {c, field_.at(c, t)}, 0);
  }

  /// Integrates over piece (a, b, c) of triangle t; returns the integral of 1 / min(F, bound)
  /// and adds the integral of 1 / F (midpoint rule) to area_integral at depth 0. Splits the
  /// piece at the midpoint of its longest edge while the gap varies (slivers along a wedge
  /// are cut across, so the pieces follow the gap's change and not the mesh's scale).
  double piece(std::size_t t, const corner& a, const corner& b, const corner& c, int depth) {
    ++pieces_;
    const point x{(a.p.x + b.p.x + c.p.x) / 3.0, (a.p.y + b.p.y + c.p.y) / 3.0};
    const double area =
        std::abs((b.p.x - a.p.x) * (c.p.y - a.p.y) - (b.p.y - a.p.y) * (c.p.x - a.p.x)) / 2.0;
    const double f = std::min(max_area_, static_cast<double>(sizing_.area_at(x)));
    const double by_area = std::isfinite(f) ? area / f : 0.0;
    if (depth == 0) area_integral += by_area;
    std::array<gap_sample, 4> s{a.gap, b.gap, c.gap, field_.at(x, t)};
    const bool centre_shielded = in_shield(s[3]);
    double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
    for (gap_sample& g : s) {
      if (g.pair.apex != no_index) g.gap = std::max(g.gap, shield_gap(g.pair.apex));
      lo = std::min(lo, bound(g));
      hi = std::max(hi, bound(g));
    }
    // no feature bound here; or the shielded corner of a small angle; or a piece too thin for
    // doubles (its midpoints would repeat its corners)
    if (!(lo < f) || centre_shielded || !(area > 0.0)) return by_area;
    // splitting a piece that holds less than a quarter of a triangle gains nothing
    if (area / lo < 0.25 || hi <= even_variation * even_variation * lo || depth >= max_depth ||
        pieces_ >= piece_budget)
      return quadrature(s, x, area, f, by_area);
    const double ab = squared(a.p, b.p), bc = squared(b.p, c.p), ca = squared(c.p, a.p);
    if (ab >= bc && ab >= ca) {
      const corner m = middle(t, a, b);
      return piece(t, a, m, c, depth + 1) + piece(t, m, b, c, depth + 1);
    }
    if (bc >= ca) {
      const corner m = middle(t, b, c);
      return piece(t, a, b, m, depth + 1) + piece(t, a, m, c, depth + 1);
    }
    const corner m = middle(t, c, a);
    return piece(t, a, b, m, depth + 1) + piece(t, m, b, c, depth + 1);
  }

  /// The integral of 1 / F (midpoint rule on the top-level pieces).
  double area_integral = 0.0;
  /// Per feature pair: what it adds.
  std::map<key, feature_excess> excess;
  std::size_t pieces() const noexcept { return pieces_; }

private:
  /// The largest triangle area a quality mesh puts at a point with this gap: c g^2, c from
  /// the kind of features (see pdd::gap_area_factor).
  double bound(const gap_sample& g) const {
    const bool across = g.pair.first.type == pslg_feature::kind::segment &&
                        g.pair.second.type == pslg_feature::kind::segment;
    return (across ? c_across_ : c_) * g.gap * g.gap;
  }

  /// The smallest feature bound at the corners, edge midpoints and centroid of triangle t.
  double triangle_bound(std::size_t t) const {
    const auto& v = field_.triangle(t);
    const pslg& g = field_.domain();
    const point a = g.vertices[v[0]], b = g.vertices[v[1]], c = g.vertices[v[2]];
    double lo = std::numeric_limits<double>::infinity();
    for (const point& p : {a, b, c, mid(a, b), mid(b, c), mid(c, a),
                           point{(a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0}}) {
      gap_sample s = field_.at(p, t);
      if (s.pair.apex != no_index) s.gap = std::max(s.gap, shield_gap(s.pair.apex));
      lo = std::min(lo, bound(s));
    }
    return lo;
  }

  static point mid(const point& p, const point& q) { return {(p.x + q.x) / 2, (p.y + q.y) / 2}; }

  static double squared(const point& p, const point& q) {
    return (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y);
  }
  corner middle(std::size_t t, const corner& p, const corner& q) const {
    const point m = mid(p.p, q.p);
    return {m, field_.at(m, t)};
  }

  /// True when the point lies in the shielded corner of a small angle (Algorithm 8.2): its gap
  /// comes from the angle's two segments and is below the shield edge. A piece whose centroid
  /// lies there counts by F alone (the mesh there is the one shielded triangle); elsewhere such
  /// a gap counts as the shield edge's length.
  bool in_shield(const gap_sample& g) const {
    return g.pair.apex != no_index && g.gap < shield_gap(g.pair.apex);
  }

  /// The length of the shield edge at a small-angle apex (pdd::shield: l = min over
  /// {(1 + 2 sin(theta/2)) sqrt(2 A sin theta), sqrt(A / sqrt 2), lfs_min}, shield edge
  /// l / (cos(theta/2) + sin theta)).
  double shield_gap(index_t apex) const {
    const double th = field_.angle_deg(apex) * std::numbers::pi / 180.0;
    double l = lfs_min_;
    if (std::isfinite(shield_area_))
      l = std::min({l,
                    (1.0 + 2.0 * std::sin(th / 2)) * std::sqrt(2.0 * shield_area_ * std::sin(th)),
                    std::sqrt(shield_area_ / std::numbers::sqrt2)});
    return l / (std::cos(th / 2) + std::sin(th));
  }

  /// Weighted mean of 1 / min(F, c g^2) at the corners (1/6 each) and the centroid (1/2),
  /// times the area; the excess over area / F goes to the centroid's feature pair.
  double quadrature(const std::array<gap_sample, 4>& s, const point& x, double area, double f,
                    double by_area) {
    const auto inv = [&](const gap_sample& g) {
      const double b = std::min(f, bound(g));
      return std::isfinite(b) && b > 0.0 ? 1.0 / b : 0.0;
    };
    const double v = area * ((inv(s[0]) + inv(s[1]) + inv(s[2])) / 6.0 + inv(s[3]) / 2.0);
    record(s[3], x, f, v - by_area);
    return v;
  }

  void record(const gap_sample& s, const point& x, double f, double added) {
    if (!(added > 0.0) || !std::isfinite(s.gap)) return;
    feature_excess& e = excess[key_of(s.pair)];
    e.integral += added;
    const double tight = bound(s) / f;
    if (tight < e.tightest) {
      e.tightest = tight;
      e.where = x;
      e.gap = s.gap;
      e.bound = f;
      e.pair = s.pair;
    }
  }

  static key key_of(const feature_pair& p) {
    if (p.apex != no_index) return {2, p.apex, 2, p.apex};
    key a{static_cast<int>(p.first.type), p.first.id, static_cast<int>(p.second.type), p.second.id};
    key b{static_cast<int>(p.second.type), p.second.id, static_cast<int>(p.first.type), p.first.id};
    return std::min(a, b);
  }

  const feature_gap_field& field_;
  double max_area_;
  const S& sizing_;
  double c_, c_across_, shield_area_, lfs_min_;
  std::size_t pieces_ = 0;
  std::size_t bounded_triangle_ = static_cast<std::size_t>(-1);
  double triangle_bound_ = 0.0;
};

} // namespace pdd::detail
