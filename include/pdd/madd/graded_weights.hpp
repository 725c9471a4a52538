/// \file graded_weights.hpp
/// Graded MADD (dissertation 4.4): subdomain density weights from boundary-vertex weights or
/// from weighted points (a background mesh's nodes, a structured grid), the split policies
/// `weight = u * area + a * density weight` (N given) and the area-ratio stopping rule
/// (required area per subdomain; the count follows from the bound).
#pragma once

#include <pdd/concepts/sizing_field.hpp>
#include <pdd/core/decomposition.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/errors.hpp>
#include <pdd/madd/detail/graded.hpp>
#include <pdd/madd/split_policy.hpp>
#include <pdd/sizing/domain_region.hpp>
#include <pdd/sizing/sizing_range.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace pdd {

/// The factors of a density-weighted graded MADD (4.4). The dissertation gives no general
/// defaults; these are the values of its Pipe and Key experiments (5.2): u = 3, a = 3,
/// p = 0.5 (its Chesapeake Bay run used u = 2, a = 3, p = 0).
struct graded_madd_options {
  double uniform_factor = 3.0; ///< u >= 0: weight of the subdomain's area
  double weight_factor = 3.0;  ///< a >= 0: weight of the subdomain's density weight
  /// p in [0, 1]: scale of the weights interpolated onto interfaces (boundary-vertex weights
  /// only); 0: interfaces weigh 0.
  double interpolation = 0.5;
};

/// \throws pdd::decomposition_error naming the bad factor.
inline void check_graded_options(const graded_madd_options& o) {
  const auto bad = [](const std::string& m) { throw decomposition_error("graded MADD: " + m); };
  if (!(o.uniform_factor >= 0.0 && std::isfinite(o.uniform_factor)))
    bad("the uniform factor u must be finite and >= 0");
  if (!(o.weight_factor >= 0.0 && std::isfinite(o.weight_factor)))
    bad("the weight factor a must be finite and >= 0");
  if (!(o.uniform_factor > 0.0 || o.weight_factor > 0.0)) bad("u and a cannot both be 0");
  if (!(o.interpolation >= 0.0 && o.interpolation <= 1.0))
    bad("the interpolation factor p must be in [0, 1]");
}

/// The first vertex attribute of every vertex of g (the .poly's density weights, 4.4 case 1).
/// \throws pdd::decomposition_error when g has no vertex attributes.
inline std::vector<double> first_vertex_attribute(const pslg& g) {
  const std::size_t na = g.vertex_attribute_count;
  if (na == 0 || g.vertex_attributes.size() != na * g.vertices.size())
    throw decomposition_error("graded MADD: the domain's vertices have no attribute to read "
                              "the boundary weights from (the .poly's <#attributes> is 0)");
  std::vector<double> w(g.vertices.size());
  for (std::size_t v = 0; v < w.size(); ++v)
    w[v] = g.vertex_attributes[v * na];
  return w;
}

/// Density weights from the PSLG's vertices (4.4, case 1). A subdomain's density weight is
/// the sum of the weights of the points of its loops, each point counted once per loop
/// position:
///  - an input vertex has its own weight (matched by exact coordinates);
///  - a point exactly on an input segment ab (a separator's end, CGAL predicates) has the
///    linear interpolation w_a + t (w_b - w_a), t = |aq| / |ab| (the boundary's own weight,
///    not scaled by p);
///  - every other point lies on an interface: the subdomain's loop is walked, and each run of
///    interface points between two boundary points A (before) and B (after) gets
///    p (W_A + s (W_B - W_A)), s the arc length from A along the run over the run's length
///    (A = B on a loop with one boundary point); on a loop that touches the input boundary
///    nowhere the interface points weigh 0.
/// So the weight is a pure function of the subdomain's points, and p = 0 gives interfaces 0.
/// A point shared by several subdomains counts for each: a subdomain on a heavy boundary stays
/// heavy however small it gets, so the splits concentrate along that boundary (p > 0 spreads
/// them inwards); madd_options::subdomains (N) ends the decomposition.
/// Thread-safety: const and shared; copies share the data.
class boundary_vertex_weights {
public:
  /// \param weights one weight per vertex of g, finite and >= 0 (e.g. the .poly's first
  /// vertex attribute, pdd::first_vertex_attribute). \throws pdd::decomposition_error for a
  /// count mismatch or a bad weight (naming the vertex), or p outside [0, 1].
  boundary_vertex_weights(const pslg& g, std::vector<double> weights, double interpolation)
      : d_(std::make_shared<data>()) {
    if (weights.size() != g.vertices.size())
      throw decomposition_error("graded MADD: " + std::to_string(weights.size()) +
                                " vertex weights for " + std::to_string(g.vertices.size()) +
                                " vertices");
    for (std::size_t v = 0; v < weights.size(); ++v)
      if (!(weights[v] >= 0.0 && std::isfinite(weights[v])))
        throw decomposition_error("graded MADD: the weight of vertex " + std::to_string(v) +
                                  " is " + std::to_string(weights[v]) +
                                  "; it must be finite and >= 0");
    if (!(interpolation >= 0.0 && interpolation <= 1.0))
      throw decomposition_error("graded MADD: the interpolation factor p must be in [0, 1]");
    d_->p = interpolation;
    d_->g = g;
    d_->w = std::move(weights);
    for (std::size_t v = 0; v < g.vertices.size(); ++v)
      d_->by_point.emplace_back(g.vertices[v], d_->w[v]);
    std::sort(d_->by_point.begin(), d_->by_point.end());
    const std::span<const point> all(g.vertices);
    const bbox world = detail::loops_box(std::span<const std::span<const point>>(&all, 1));
    d_->segments = detail::bucket_grid(world, g.segments.size());
    for (std::size_t s = 0; s < g.segments.size(); ++s)
      d_->segments.insert(s, segment_box(s));
  }

  /// The density weight of one subdomain.
  double leaf_weight(const madd_leaf_view& leaf) const {
    double sum = 0.0;
    for (const auto& loop : leaf.loops) {
      std::vector<char> anchor(loop.size(), 0);
      std::vector<double> value(loop.size(), 0.0);
      for (std::size_t i = 0; i < loop.size(); ++i)
        anchor[i] = boundary_weight(loop[i], value[i]) ? 1 : 0;
      detail::interpolate_interfaces(loop, anchor, value, d_->p);
      for (const double v : value)
        sum += v;
    }
    return sum;
  }
  /// The density weight of every leaf.
  std::vector<double> operator()(std::span<const madd_leaf_view> leaves) const {
    return detail::weigh_leaves(leaves, [this](const madd_leaf_view& l) { return leaf_weight(l); });
  }

  /// The weight W(q) of the input boundary at q (a vertex's weight, or interpolated along the
  /// lowest-numbered input segment through q); false when q is on no input segment.
  bool boundary_weight(const point& q, double& w) const {
    const auto it = std::lower_bound(d_->by_point.begin(), d_->by_point.end(),
                                     std::pair<point, double>{q, -1.0});
    if (it != d_->by_point.end() && it->first == q) {
      w = it->second;
      return true;
    }
    std::size_t best = d_->g.segments.size();
    d_->segments.for_each_in({q.x, q.y, q.x, q.y}, [&](std::size_t s) {
      const segment& e = d_->g.segments[s];
      if (s < best && detail::on_segment(q, d_->g.vertices[e.a], d_->g.vertices[e.b])) best = s;
    });
    if (best == d_->g.segments.size()) return false;
    const segment& e = d_->g.segments[best];
    const point &a = d_->g.vertices[e.a], &b = d_->g.vertices[e.b];
    const double len = detail::distance(a, b);
    const double t = len > 0.0 ? detail::distance(a, q) / len : 0.0;
    w = d_->w[e.a] + t * (d_->w[e.b] - d_->w[e.a]);
    return true;
  }

private:
  struct data {
    pslg g;
    std::vector<double> w;
    std::vector<std::pair<point, double>> by_point;
    detail::bucket_grid segments;
    double p = 0.0;
  };
  bbox segment_box(std::size_t s) const {
    const point &a = d_->g.vertices[d_->g.segments[s].a], &b = d_->g.vertices[d_->g.segments[s].b];
    return {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
  }
  std::shared_ptr<data> d_;
};

/// Density weights from weighted points (4.4, cases 2 and 3): the nodes of a background
/// mesh, or the nodes of a structured grid on which a weight function was evaluated. A
/// subdomain's density weight is the sum of the weights of the points in it, closed: a point
/// on a subdomain's boundary counts for every subdomain whose boundary holds it (exact
/// point-in-polygon tests, CGAL predicates). Points are found through a bucket grid; the sum
/// runs in point order, so it is bitwise reproducible.
/// Thread-safety: const and shared; copies share the points.
class point_weights {
public:
  /// \throws pdd::decomposition_error for a count mismatch, a non-finite point or a weight
  /// not finite and >= 0 (naming the point).
  point_weights(std::vector<point> points, std::vector<double> weights)
      : d_(std::make_shared<data>()) {
    if (points.size() != weights.size())
      throw decomposition_error("graded MADD: " + std::to_string(weights.size()) + " weights for " +
                                std::to_string(points.size()) + " points");
    for (std::size_t i = 0; i < points.size(); ++i)
      if (!(weights[i] >= 0.0 && std::isfinite(weights[i])) || !std::isfinite(points[i].x) ||
          !std::isfinite(points[i].y))
        throw decomposition_error("graded MADD: weighted point " + std::to_string(i) + " (" +
                                  std::to_string(points[i].x) + ", " + std::to_string(points[i].y) +
                                  ") has weight " + std::to_string(weights[i]) +
                                  "; it must be finite and >= 0");
    const std::span<const point> all(points);
    d_->index = detail::bucket_grid(
        detail::loops_box(std::span<const std::span<const point>>(&all, 1)), points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
      d_->index.insert(i, {points[i].x, points[i].y, points[i].x, points[i].y});
    d_->points = std::move(points);
    d_->weights = std::move(weights);
  }

  /// The weights of f evaluated at the nodes (x0 + i dx, y0 + j dy), i < nx, j < ny, of a
  /// structured grid (4.4, case 3). \tparam F callable point -> double.
  template <class F>
  static point_weights on_grid(point origin, double dx, double dy, std::size_t nx, std::size_t ny,
                               F&& f) {
    std::vector<point> pts;
    std::vector<double> w;
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i) {
        pts.push_back(
            {origin.x + static_cast<double>(i) * dx, origin.y + static_cast<double>(j) * dy});
        w.push_back(f(pts.back()));
      }
    return {std::move(pts), std::move(w)};
  }

  /// The ids of the points in the closed leaf, increasing.
  std::vector<std::size_t> points_in(const madd_leaf_view& leaf) const {
    const detail::leaf_polygons poly(leaf);
    std::vector<std::size_t> ids;
    d_->index.for_each_in(detail::loops_box(leaf.loops), [&](std::size_t i) { ids.push_back(i); });
    std::sort(ids.begin(), ids.end());
    ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    std::erase_if(ids, [&](std::size_t i) { return !poly.contains(d_->points[i]); });
    return ids;
  }
  /// The density weight of one subdomain.
  double leaf_weight(const madd_leaf_view& leaf) const {
    double sum = 0.0;
    for (const std::size_t i : points_in(leaf))
      sum += d_->weights[i];
    return sum;
  }
  /// The density weight of every leaf.
  std::vector<double> operator()(std::span<const madd_leaf_view> leaves) const {
    return detail::weigh_leaves(leaves, [this](const madd_leaf_view& l) { return leaf_weight(l); });
  }
  /// The number of weighted points.
  std::size_t size() const noexcept { return d_->points.size(); }

private:
  struct data {
    std::vector<point> points;
    std::vector<double> weights;
    detail::bucket_grid index;
  };
  std::shared_ptr<data> d_;
};

/// The split policy of a density-weighted graded MADD (4.4): every leaf's priority is
/// u * area + a * density weight, so the heaviest leaf is split first, until
/// madd_options::subdomains leaves exist (a leaf of priority 0, e.g. u = 0 and no weight,
/// is left as it is). \tparam Weights callable span<const madd_leaf_view> ->
/// std::vector<double> (boundary_vertex_weights, point_weights).
/// \throws pdd::decomposition_error for bad factors (check_graded_options).
template <class Weights>
madd_split_policy density_weight_policy(Weights weights, const graded_madd_options& o) {
  check_graded_options(o);
  return [weights = std::move(weights), u = o.uniform_factor,
          a = o.weight_factor](std::span<const madd_leaf_view> leaves) {
    std::vector<double> w = weights(leaves);
    for (std::size_t i = 0; i < leaves.size(); ++i)
      w[i] = u * leaves[i].area + a * w[i];
    return w;
  };
}

/// The required area of each leaf for the area-ratio rule (4.4): a true lower bound of the
/// required-area function F over the leaf itself, pdd::sizing_range(F, region).lo (from the
/// nodes around its box for background meshes and grids; for callables the documented grid
/// rule with samples in the leaf only). The dissertation takes the minimum of F at the
/// background points inside the subdomain; the lower bound over the leaf is never larger, so
/// the rule below holds for every point of every final subdomain, not only at the sample
/// points. Infinity where F sets no bound.
template <SizingField F>
std::vector<double> required_areas(const F& f, std::span<const madd_leaf_view> leaves) {
  std::vector<double> r;
  r.reserve(leaves.size());
  for (const auto& l : leaves)
    r.push_back(sizing_range(f, loops_region(l.loops).view()).lo);
  return r;
}

/// The split policy of the area-ratio graded MADD (4.4): the leaf with the largest
/// area / required area is split first, and a leaf whose ratio is <= max_ratio is
/// acceptable; so no final subdomain has a ratio above max_ratio (the dissertation's
/// default bound is 1), and the count follows from the bound (madd_options::subdomains
/// only caps it). \tparam F a SizingField: the required subdomain area at each point.
/// \throws pdd::decomposition_error when max_ratio is not finite and > 0.
template <SizingField F>
madd_split_policy area_ratio_policy(F required_area, double max_ratio = 1.0) {
  if (!(max_ratio > 0.0 && std::isfinite(max_ratio)))
    throw decomposition_error("graded MADD: the area ratio bound must be finite and > 0");
  return [f = std::move(required_area), max_ratio](std::span<const madd_leaf_view> leaves) {
    std::vector<double> r = required_areas(f, leaves);
    for (std::size_t i = 0; i < leaves.size(); ++i) {
      const double ratio = leaves[i].area / r[i];
      r[i] = ratio > max_ratio ? ratio : 0.0;
    }
    return r;
  };
}

/// The subdomains of a decomposition as the leaves a split policy sees (for reporting the
/// weights or area ratios of the final subdomains). The views point into `points`.
struct decomposition_leaves {
  /// points[s][l]: the points of loop l of subdomain s (as decomposition::subdomains[s].loops).
  std::vector<std::vector<std::vector<point>>> points;
  /// One leaf view per subdomain, in subdomain order, each pointing into `points`.
  std::vector<madd_leaf_view> views;
};

/// \pre d is a valid decomposition (pdd::validate_decomposition).
inline decomposition_leaves leaves_of(const decomposition& d) {
  decomposition_leaves r;
  r.points.resize(d.subdomains.size());
  r.views.resize(d.subdomains.size());
  for (std::size_t s = 0; s < d.subdomains.size(); ++s) {
    for (const auto& loop : d.subdomains[s].loops) {
      r.points[s].emplace_back();
      for (const auto v : loop)
        r.points[s].back().push_back(d.vertices[v]);
    }
    for (const auto& loop : r.points[s])
      r.views[s].loops.emplace_back(loop);
    r.views[s].area = d.subdomains[s].area;
  }
  return r;
}

} // namespace pdd
