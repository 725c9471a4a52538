/// \file refine.hpp
/// Ruppert's Delaunay refinement (Ruppert 1995; Shewchuk 1997 ch. 3, 2002) on the native
/// triangulation, restricted to the domain: encroached subsegments are split first (at the
/// midpoint, or on a concentric shell next to an input vertex); then a bad triangle (over its
/// area bound first, the last queued first; then the skinny ones, the shortest edge first,
/// from a bucketed queue) gets its refinement point (detail::off_centre), unless that point
/// encroaches a subsegment, which is split instead and the triangle reconsidered. A subsegment
/// is encroached only by a vertex on a domain side of it (as in pdd::cgal::mesher), in its
/// diametral disk or, on an input segment under segment_encroachment::diametral_lens, in its
/// lens (Chew; Triangle's rule without -D); a refinement point a segment hides from its
/// triangle encroaches the segment under either rule.
///
/// Small input angles (Shewchuk 2002, sec. 3.7 / Shewchuk 1997 sec. 3.5): with concentric
/// shells, the two segments of a small angle are split at equal distances from its apex; a
/// triangle that is bad only in shape and whose shortest edge joins two such vertices on the
/// same shell (two segments meeting at an input vertex at an angle below 60 deg) is left
/// unrefined: its small angle is forced by the input angle, and refining it would cascade
/// into ever smaller splits. Shielded domains (dissertation 8.1) have no such angle, so there
/// every triangle meets the bound.
#pragma once

#include <pdd/concepts/sizing_field.hpp>
#include <pdd/core/mesh_criteria.hpp>
#include <pdd/core/triangle_measures.hpp>
#include <pdd/kernels/detail/encroachment.hpp>
#include <pdd/kernels/detail/off_centre.hpp>
#include <pdd/kernels/native/detail/insertion.hpp>
#include <pdd/kernels/native/detail/segments.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace pdd::detail::native_mesh {

/// The bad-triangle queue: one bucket of over-area triangles, then 2200 of skinny ones by the
/// binary logarithm of their shortest edge's square (shortest first, the order of Triangle
/// 1.6's queue). The smallest angle first, as before, made many more triangles near the angle
/// bounds Triangle is used at, since an off-centre refines a short edge's neighbourhood once
/// where the worst-angle order reaches it through larger triangles first: 20,000 random points
/// in the unit square, no area bound, 187,569 against Triangle's 142,125 at 32.5 deg and
/// 441,368 against 171,726 at 33.8 deg; 145,702 and 179,299 now.
///
/// Within a bucket the last triangle queued is refined first, so the new triangles of an
/// insertion are refined next, while their memory is in cache. Over-area triangles used to go
/// to 32 buckets by their excess, largest first: that refines the whole domain one halving of
/// the area at a time, each sweep over cold memory, with every triangle of a level waiting in
/// the queue (on the pipe at 4M triangles the queue's growth was a third of the run's page
/// faults); one last-in first-out bucket refines depth first, each region down to its bound
/// while it is in cache (the kernel's time per triangle fell by a fifth, for about 1% fewer
/// triangles). Entries carry the corners so that a rewritten slot is recognised as stale.
class bad_queue {
public:
  struct entry {
    std::uint32_t t;
    std::array<index_t, 3> c;
  };
  static constexpr int buckets = 1 + 2200;
  /// The over-area bucket.
  static constexpr int over_area = 0;
  /// The first skinny bucket; the squared shortest edge 2^e goes to skinny + e + 1100.
  static constexpr int skinny = 1;

  void push(int bucket, const entry& e) {
    q_[static_cast<std::size_t>(bucket)].push_back(e);
    if (bucket < first_) first_ = bucket;
  }
  bool pop(entry& e) {
    for (; first_ < buckets; ++first_) {
      auto& b = q_[static_cast<std::size_t>(first_)];
      if (!b.empty()) {
        e = b.back();
        b.pop_back();
        return true;
      }
    }
    return false;
  }

private:
  std::array<std::vector<entry>, buckets> q_;
  int first_ = buckets;
};

/// The refinement of one triangulation. \tparam S a SizingField.
template <SizingField S>
class refiner {
public:
  refiner(triangulation& tr, cavity& cav, segment_ids& ids, const pslg& d, const mesh_criteria& c,
          const S& sizing)
      : tr_(tr), cav_(cav), ids_(ids), d_(d), shape_bound_(c.shape_bound()), max_area_(c.max_area),
        lens_cosine_(c.lens_cosine()), lens_(uses_diametral_lens(d, c)), sizing_(sizing) {}

  /// Refines until no subsegment is encroached and no triangle of the domain is bad (except
  /// those left at small input angles, see the file comment).
  void run() {
    scan();
    bad_queue::entry e{};
    for (;;) {
      split_encroached();
      if (!bad_.pop(e)) break;
      const auto& now = tr_.corner(e.t);
      if (now[0] != e.c[0] || now[1] != e.c[1] || now[2] != e.c[2] || !tr_.in_domain(e.t)) continue;
      const quality q = measure(e.t);
      if (q.bucket < 0 || (!q.over_area && at_small_input_angle(e.t))) continue;
      refine_triangle(e);
    }
  }

private:
  struct quality {
    int bucket = -1; ///< queue bucket; -1: not bad
    bool over_area = false;
    double excess = 0.0; ///< area / area bound, when over_area
  };

  quality measure(std::uint32_t t) const {
    const point &a = tr_.at(t, 0), &b = tr_.at(t, 1), &c = tr_.at(t, 2);
    const double bound =
        std::min(max_area_, static_cast<double>(sizing_.area_at(triangle_centroid(a, b, c))));
    const double area = triangle_area(a, b, c);
    if (area > bound) return {bad_queue::over_area, true, area / bound};
    if (!(squared_sine_min_angle(a, b, c) < shape_bound_)) return {};
    const auto l2 = [](const point& p, const point& q) {
      return (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y);
    };
    const double shortest = std::min({l2(a, b), l2(b, c), l2(c, a)});
    return {bad_queue::skinny + std::clamp(std::ilogb(shortest) + 1100, 0, 2199), false};
  }

  void push_if_bad(std::uint32_t t) {
    const quality q = measure(t);
    if (q.bucket >= 0) bad_.push(q.bucket, {t, tr_.corner(t)});
  }

  /// A vertex on a domain side of constrained edge i of t encroaches it (encroaches).
  bool encroached(std::uint32_t t, int i) const {
    if (tr_.in_domain(t) && encroaches(t, i, tr_.at(t, i))) return true;
    const ref_t n = tr_.adj(t)[i];
    return n != no_ref && tr_.in_domain(ref_tri(n)) &&
           encroaches(t, i, tr_.at(ref_tri(n), ref_edge(n)));
  }

  /// p lies in the closed diametral disk of constrained edge i of t (exact) and, on an input
  /// segment under segment_encroachment::diametral_lens, in its lens as well.
  bool encroaches(std::uint32_t t, int i, const point& p) const {
    const point &a = tr_.at(t, next3(i)), &b = tr_.at(t, prev3(i));
    if (!in_diametral_disk(a, b, p)) return false;
    return !lens_ || in_diametral_lens(a, b, p, lens_cosine_);
  }

  void queue_if_encroached(std::uint32_t t, int i) {
    if (tr_.constrained(t, i) && encroached(t, i))
      segments_.emplace_back(tr_.corner(t)[next3(i)], tr_.corner(t)[prev3(i)]);
  }

  void scan() {
    for (std::uint32_t t = 0; t < tr_.size(); ++t) {
      if (tr_.in_domain(t)) push_if_bad(t);
      for (int i = 0; i < 3; ++i)
        if (tr_.adj(t)[i] != no_ref && ref_tri(tr_.adj(t)[i]) > t) queue_if_encroached(t, i);
    }
  }

  /// New triangles: queue the bad ones and the encroached subsegments on their edges. The
  /// new triangles over their area bound go on the last-in first-out bucket the smallest excess
  /// first, so that the largest is refined first: the depth-first order's locality with the
  /// largest-first order's sizes (about 1 % fewer triangles than in fan order: the pipe at 4M
  /// 4,068,872 against 4,105,287; Triangle 4,067,653; for about 3 % more time).
  void after_insertion() {
    over_area_.clear();
    for (const std::uint32_t t : cav_.created()) {
      if (tr_.in_domain(t)) {
        const quality q = measure(t);
        if (q.over_area)
          over_area_.emplace_back(q.excess, t);
        else if (q.bucket >= 0)
          bad_.push(q.bucket, {t, tr_.corner(t)});
      }
      for (int i = 0; i < 3; ++i)
        queue_if_encroached(t, i);
    }
    std::sort(over_area_.begin(), over_area_.end());
    for (const auto& [excess, t] : over_area_)
      bad_.push(bad_queue::over_area, {t, tr_.corner(t)});
  }

  void split_encroached() {
    for (std::size_t k = 0; k < segments_.size(); ++k) {
      const ref_t r = tr_.find_edge(segments_[k].first, segments_[k].second);
      if (r != no_ref && tr_.constrained(ref_tri(r), ref_edge(r)) &&
          encroached(ref_tri(r), ref_edge(r)))
        split_segment(r);
    }
    segments_.clear();
  }

  /// Splits the subsegment of edge reference r (Ruppert's concentric shells, segments.hpp).
  void split_segment(ref_t r) {
    const std::uint32_t t = ref_tri(r);
    const int i = ref_edge(r);
    const index_t a = tr_.corner(t)[next3(i)], b = tr_.corner(t)[prev3(i)];
    const point m = split_point(tr_.pts[a], ids_.is_input(a), tr_.pts[b], ids_.is_input(b));
    const index_t seg = ids_.of_edge(a, b);
    if ((m.x == tr_.pts[a].x && m.y == tr_.pts[a].y) ||
        (m.x == tr_.pts[b].x && m.y == tr_.pts[b].y))
      throw unresolvable_input_error(-1, "segment " + std::to_string(seg) +
                                             " would be split into pieces below the "
                                             "floating-point resolution (the bounds ask for too "
                                             "fine a mesh, or two segments meet at too small an "
                                             "angle)");
    cav_.grow(tr_, m, {t, ref_tri(tr_.adj(t)[i])}, r);
    if (!cav_.make_star_shaped(tr_, m, 2))
      throw meshing_error(-1, "internal error: split point of segment " + std::to_string(seg) +
                                  " is not visible from its segment");
    const auto v = static_cast<index_t>(tr_.pts.size());
    tr_.pts.push_back(m);
    ids_.of_vertex.push_back(seg);
    cav_.set_split_endpoints(a, b);
    cav_.commit(tr_, v);
    after_insertion();
  }

  /// Inserts the refinement point of a bad triangle (its off-centre or circumcentre,
  /// detail::off_centre), or queues the subsegments it encroaches and the triangle again.
  void refine_triangle(const bad_queue::entry& e) {
    const point &a = tr_.at(e.t, 0), &b = tr_.at(e.t, 1), &c = tr_.at(e.t, 2);
    const auto cc = CGAL::circumcenter(cp(a), cp(b), cp(c));
    const point p = off_centre(a, b, c, point{cc.x(), cc.y()}, shape_bound_);
    cav_.grow(tr_, p, {e.t}, no_ref);
    const std::vector<ref_t>& enc = cav_.encroached_segments(
        tr_, p, [this](std::uint32_t t, int i, const point& q) { return encroaches(t, i, q); });
    if (!enc.empty()) {
      forced_.clear();
      for (const ref_t r : enc)
        forced_.emplace_back(tr_.corner(ref_tri(r))[next3(ref_edge(r))],
                             tr_.corner(ref_tri(r))[prev3(ref_edge(r))]);
      cav_.clear(tr_);
      for (const auto& s : forced_)
        force_split(s);
      if (tr_.in_domain(e.t)) push_if_bad(e.t);
      return;
    }
    if (!cav_.make_star_shaped(tr_, p, 1))
      throw meshing_error(-1, "internal error: a circumcentre is not visible from its triangle");
    const auto v = static_cast<index_t>(tr_.pts.size());
    tr_.pts.push_back(p);
    ids_.of_vertex.push_back(no_index);
    cav_.commit(tr_, v);
    after_insertion();
  }

  /// Splits a subsegment that a circumcentre encroaches, if it is still an edge.
  void force_split(std::pair<index_t, index_t> s) {
    const ref_t r = tr_.find_edge(s.first, s.second);
    if (r != no_ref && tr_.constrained(ref_tri(r), ref_edge(r))) split_segment(r);
  }

  /// Shewchuk's rule for small input angles (file comment): the shortest edge of t joins
  /// Steiner vertices on two segments that meet at an input vertex at less than 60 deg, at
  /// the same distance from it (within 1%: both on one concentric shell).
  bool at_small_input_angle(std::uint32_t t) const {
    int k = 0;
    double shortest = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i) {
      const double l = squared_distance(tr_.at(t, next3(i)), tr_.at(t, prev3(i)));
      if (l < shortest) shortest = l, k = i;
    }
    const index_t p = tr_.corner(t)[next3(k)], q = tr_.corner(t)[prev3(k)];
    const index_t sp = ids_.of_vertex[p], sq = ids_.of_vertex[q];
    if (sp == no_index || sq == no_index || sp == sq) return false;
    const segment &x = d_.segments[sp], &y = d_.segments[sq];
    const index_t apex = x.a == y.a || x.a == y.b ? x.a : x.b == y.a || x.b == y.b ? x.b : no_index;
    if (apex == no_index) return false;
    const point& w = tr_.pts[apex];
    const point& u = tr_.pts[x.a == apex ? x.b : x.a];
    const point& v = tr_.pts[y.a == apex ? y.b : y.a];
    const double dot = (u.x - w.x) * (v.x - w.x) + (u.y - w.y) * (v.y - w.y);
    if (!(dot > 0.5 * std::sqrt(squared_distance(u, w) * squared_distance(v, w)))) return false;
    const double ratio = squared_distance(w, tr_.pts[p]) / squared_distance(w, tr_.pts[q]);
    return ratio > 0.98 && ratio < 1.02;
  }

  triangulation& tr_;
  cavity& cav_;
  segment_ids& ids_;
  const pslg& d_;
  double shape_bound_, max_area_, lens_cosine_;
  bool lens_; ///< refined under the lens (uses_diametral_lens)
  const S& sizing_;
  bad_queue bad_;
  std::vector<std::pair<index_t, index_t>> segments_, forced_;
  std::vector<std::pair<double, std::uint32_t>> over_area_; ///< after_insertion's scratch
};

} // namespace pdd::detail::native_mesh
