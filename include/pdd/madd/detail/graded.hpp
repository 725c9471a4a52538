/// \file graded.hpp
/// Implementation detail of the graded MADD weights (dissertation 4.4): a bucket grid over
/// points and boxes, exact point-in-leaf tests, and the classification of a leaf's loop points
/// against the input boundary.
#pragma once

#include <pdd/core/bbox.hpp>
#include <pdd/core/kernel.hpp>
#include <pdd/core/point.hpp>
#include <pdd/madd/detail/region.hpp>
#include <pdd/madd/split_policy.hpp>

#include <CGAL/Polygon_2_algorithms.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

namespace pdd::detail {

/// The bounding box of a set of loops.
inline bbox loops_box(std::span<const std::span<const point>> loops) {
  bbox b;
  for (const auto& loop : loops)
    for (const point& p : loop) {
      b.xmin = std::min(b.xmin, p.x);
      b.ymin = std::min(b.ymin, p.y);
      b.xmax = std::max(b.xmax, p.x);
      b.ymax = std::max(b.ymax, p.y);
    }
  return b;
}

/// A uniform grid of cells over a box; items (ids) are registered in every cell their box
/// meets. The cell of a coordinate is a monotone function of it, so a point inside an item's
/// box always lies in a cell the item is registered in (no tolerance needed).
class bucket_grid {
public:
  bucket_grid() = default;
  /// About `items` cells in all over `world` (at least one).
  bucket_grid(const bbox& world, std::size_t items) : world_(world) {
    const double side = std::sqrt(static_cast<double>(std::max<std::size_t>(items, 1)));
    n_ = std::clamp<std::size_t>(static_cast<std::size_t>(side), 1, 2048);
    cells_.resize(n_ * n_);
  }
  void insert(std::size_t id, const bbox& b) {
    for (std::size_t j = cell(b.ymin, world_.ymin, world_.ymax);
         j <= cell(b.ymax, world_.ymin, world_.ymax); ++j)
      for (std::size_t i = cell(b.xmin, world_.xmin, world_.xmax);
           i <= cell(b.xmax, world_.xmin, world_.xmax); ++i)
        cells_[j * n_ + i].push_back(id);
  }
  /// Calls f(id) for every item registered in a cell that b meets (an id can come twice when
  /// items span several cells).
  template <class F>
  void for_each_in(const bbox& b, F&& f) const {
    if (cells_.empty() || b.empty()) return;
    for (std::size_t j = cell(b.ymin, world_.ymin, world_.ymax);
         j <= cell(b.ymax, world_.ymin, world_.ymax); ++j)
      for (std::size_t i = cell(b.xmin, world_.xmin, world_.xmax);
           i <= cell(b.xmax, world_.xmin, world_.xmax); ++i)
        for (const std::size_t id : cells_[j * n_ + i])
          f(id);
  }

private:
  std::size_t cell(double v, double lo, double hi) const {
    if (!(hi > lo)) return 0;
    const double t = std::floor((v - lo) / (hi - lo) * static_cast<double>(n_));
    return static_cast<std::size_t>(std::clamp(t, 0.0, static_cast<double>(n_ - 1)));
  }
  bbox world_;
  std::size_t n_ = 0;
  std::vector<std::vector<std::size_t>> cells_;
};

/// A leaf's loops as CGAL points, for exact point-in-leaf tests.
struct leaf_polygons {
  explicit leaf_polygons(const madd_leaf_view& v) {
    for (const auto& loop : v.loops) {
      polys.emplace_back();
      for (const point& p : loop)
        polys.back().emplace_back(p.x, p.y);
    }
  }
  /// Whether q lies in the closed leaf: inside or on the outer loop, and not strictly inside
  /// a hole (exact predicates).
  bool contains(const point& q) const {
    const epick::Point_2 c(q.x, q.y);
    if (polys.empty() || CGAL::bounded_side_2(polys[0].begin(), polys[0].end(), c, epick()) ==
                             CGAL::ON_UNBOUNDED_SIDE)
      return false;
    for (std::size_t h = 1; h < polys.size(); ++h)
      if (CGAL::bounded_side_2(polys[h].begin(), polys[h].end(), c, epick()) ==
          CGAL::ON_BOUNDED_SIDE)
        return false;
    return true;
  }
  std::vector<std::vector<epick::Point_2>> polys;
};

/// Whether q lies on the closed segment ab (exact predicates).
inline bool on_segment(const point& q, const point& a, const point& b) {
  const epick::Point_2 pa(a.x, a.y), pb(b.x, b.y), pq(q.x, q.y);
  return CGAL::collinear(pa, pb, pq) && CGAL::collinear_are_ordered_along_line(pa, pq, pb);
}

/// The weights of the points of one loop from the weights of its boundary anchors (the points
/// on the input boundary, anchor[i] true, value[i] their boundary weight): every other point
/// (on an interface) gets p times the linear interpolation, by arc length along the loop,
/// between the nearest anchor before it and the nearest anchor after it. A loop without
/// anchors weighs 0 everywhere.
inline void interpolate_interfaces(std::span<const point> loop, const std::vector<char>& anchor,
                                   std::vector<double>& value, double p) {
  const std::size_t n = loop.size();
  std::size_t first = n;
  for (std::size_t i = 0; i < n && first == n; ++i)
    if (anchor[i]) first = i;
  if (first == n) {
    std::fill(value.begin(), value.end(), 0.0);
    return;
  }
  // walk the loop once from the first anchor: each run of interface points lies between the
  // anchor `a` before it and the next anchor after it
  std::size_t a = first;
  for (std::size_t step = 1; step <= n; ++step) {
    const std::size_t i = (first + step) % n;
    if (!anchor[i]) continue;
    double total = 0.0;
    for (std::size_t k = a; k != i; k = (k + 1) % n)
      total += distance(loop[k], loop[(k + 1) % n]);
    double s = 0.0;
    for (std::size_t k = (a + 1) % n; k != i; k = (k + 1) % n) {
      s += distance(loop[(k + n - 1) % n], loop[k]);
      const double t = total > 0.0 ? s / total : 0.5;
      value[k] = p * (value[a] + t * (value[i] - value[a]));
    }
    a = i;
  }
}

/// One weight per leaf: weigh(leaf) for every leaf, in order (the split policies' answer).
template <class Weigh>
std::vector<double> weigh_leaves(std::span<const madd_leaf_view> leaves, const Weigh& weigh) {
  std::vector<double> w;
  w.reserve(leaves.size());
  for (const auto& l : leaves)
    w.push_back(weigh(l));
  return w;
}

} // namespace pdd::detail
