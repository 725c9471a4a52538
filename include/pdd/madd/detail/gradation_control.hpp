/// \file gradation_control.hpp
/// Implementation of pdd::gradation_controlled_decompose (dissertation 7.3, Algorithm 7.1,
/// Condition 3 of 7.6): the measures of a leaf (m, M, expected triangles), the neighbours of
/// the leaves from their shared edges, and the split policy that marks non-acceptable leaves.
#pragma once

#include <pdd/core/bbox.hpp>
#include <pdd/core/point.hpp>
#include <pdd/core/pslg.hpp>
#include <pdd/madd/split_policy.hpp>
#include <pdd/parallel/parallel_for.hpp>
#include <pdd/sizing/any_sizing.hpp>
#include <pdd/sizing/domain_region.hpp>
#include <pdd/sizing/inverse_area_integral.hpp>
#include <pdd/sizing/sizing_range.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <limits>
#include <span>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace pdd::detail {

/// m(D), M(D) (bounds of min(max_area, F) over the leaf's bounding box, m a true lower bound)
/// and the expected triangles of a leaf (integral of 1 / (f min(max_area, F)), Algorithm 7.2).
struct leaf_measure {
  double lo = 0.0;
  double hi = 0.0;
  double expected = 0.0;
};

/// Which of Conditions 1-3 a leaf fails (bit 0: M > R1 m; bit 1: m > R2 m' or m' > R2 m for a
/// neighbour; bit 2: more than T expected triangles).
enum : unsigned { fails_condition_1 = 1u, fails_condition_2 = 2u, fails_condition_3 = 4u };

/// The measuring rule shared by the split policy and the final report.
struct leaf_measuring {
  any_sizing field;
  double max_area = std::numeric_limits<double>::infinity();
  double mean_area_fraction = 0.656;
  std::size_t samples = 1024;           ///< midpoint-rule pieces of the expected-triangles integral
  sizing_range_options range_options{}; ///< gradation_options::range

  /// \pre loops[0] is the outer loop (points, any orientation), loops[1..] the holes.
  leaf_measure operator()(std::span<const std::vector<point>> loops) const {
    pslg g;
    for (const auto& loop : loops)
      g.add_loop(loop);
    const std::vector<domain_triangle> triangles = domain_faces(g).triangles();
    const sizing_bounds r =
        sizing_range(field, domain_region(g.vertices, triangles).view(), range_options);
    const double integral = inverse_area_integral(g.vertices, triangles, max_area, field, samples);
    return {std::min(max_area, r.lo), std::min(max_area, r.hi), integral / mean_area_fraction};
  }
};

/// Canonical edge key: the lexicographically smaller endpoint first (leaves sharing an edge
/// store bitwise-identical endpoints).
struct edge_key {
  point a, b;
  bool operator==(const edge_key& o) const noexcept {
    return a.x == o.a.x && a.y == o.a.y && b.x == o.b.x && b.y == o.b.y;
  }
};
struct edge_key_hash {
  std::size_t operator()(const edge_key& e) const noexcept {
    std::uint64_t h = 0x9e3779b97f4a7c15ull;
    for (const double v : {e.a.x, e.a.y, e.b.x, e.b.y})
      h = (h ^ std::bit_cast<std::uint64_t>(v)) * 0x100000001b3ull + (h >> 29);
    return static_cast<std::size_t>(h);
  }
};
inline edge_key canonical_edge(point p, point q) {
  if (q.x < p.x || (q.x == p.x && q.y < p.y)) std::swap(p, q);
  return {p, q};
}

/// The pairs (i, j), i < j, of leaves that share an edge, sorted, each once.
/// Complexity O(total loop size) expected.
template <class LoopsOf>
std::vector<std::pair<std::size_t, std::size_t>> shared_edge_pairs(std::size_t n,
                                                                   LoopsOf&& loops_of) {
  std::unordered_map<edge_key, std::size_t, edge_key_hash> owner;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < n; ++i)
    for (const auto& loop : loops_of(i))
      for (std::size_t k = 0; k < loop.size(); ++k) {
        const auto [it, inserted] =
            owner.emplace(canonical_edge(loop[k], loop[(k + 1) % loop.size()]), i);
        if (!inserted && it->second != i)
          pairs.emplace_back(std::min(it->second, i), std::max(it->second, i));
      }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

/// The conditions every leaf fails (bit set of fails_condition_*), from its measures and the
/// neighbour pairs. A leaf with m = infinity (no bound anywhere in it) fails none of 1-2. A
/// leaf that MADD keeps whole (`whole[i]`, a cap around a small angle between faces) fails
/// none, and no neighbour fails Condition 2 against it: no split can change the cap, whose m
/// comes from the features it encloses, so holding its neighbours to it would split them
/// without end (la.poly: 4096 subdomains at the cap). Condition 2 only keeps k_i varying
/// slowly; pdd::decouple_graded checks relation 7.1 on every separator segment and lowers k
/// beside the cap where it must.
inline std::vector<unsigned>
failed_conditions(const std::vector<leaf_measure>& m,
                  const std::vector<std::pair<std::size_t, std::size_t>>& pairs, double r1,
                  double r2, double t, const std::vector<bool>& whole = {}) {
  const auto kept_whole = [&](std::size_t i) { return i < whole.size() && whole[i]; };
  std::vector<unsigned> fail(m.size(), 0u);
  for (std::size_t i = 0; i < m.size(); ++i) {
    if (kept_whole(i)) continue;
    if (std::isfinite(m[i].lo) && m[i].hi > r1 * m[i].lo) fail[i] |= fails_condition_1;
    if (m[i].expected > t) fail[i] |= fails_condition_3;
  }
  for (const auto& pr : pairs) {
    if (kept_whole(pr.first) || kept_whole(pr.second)) continue;
    const double a = m[pr.first].lo, b = m[pr.second].lo;
    if (a > r2 * b || b > r2 * a) {
      fail[pr.first] |= fails_condition_2;
      fail[pr.second] |= fails_condition_2;
    }
  }
  return fail;
}

/// The mutable state of the Algorithm 7.1 split policy: the rule, a cache of leaf measures
/// (keyed by the leaf's area and bounding box, bitwise: a leaf keeps both when boundary points
/// of a neighbour's split are added to it) and what the last call saw (for error messages).
struct gradation_policy_state {
  leaf_measuring measure;
  double r1 = 1.425, r2 = 1.5, t = std::numeric_limits<double>::infinity();
  double min_triangles = 0.0;
  std::size_t min_leaves = 1;
  std::unordered_map<std::string, leaf_measure> cache;
  std::vector<leaf_measure> last;
  std::vector<unsigned> last_fail;
  std::vector<double> last_priority;
  /// key_of(outer loop, 0) of every leaf of the last call -> its index (the final report
  /// finds the measures of the assembled subdomains there).
  std::unordered_map<std::string, std::size_t> last_index;

  /// The bitwise key of a box of points, their count (a leaf that a neighbour's split gave a
  /// vertex on an edge is measured anew: the measure samples its vertices) and an area.
  template <class Loop>
  static std::string key_of(const Loop& outer, double area) {
    pdd::bbox b;
    for (const point& p : outer)
      b = {std::min(b.xmin, p.x), std::min(b.ymin, p.y), std::max(b.xmax, p.x),
           std::max(b.ymax, p.y)};
    std::string k(6 * sizeof(double), '\0');
    const double vals[6] = {b.xmin, b.ymin, b.xmax,
                            b.ymax, area,   static_cast<double>(outer.size())};
    for (int i = 0; i < 6; ++i)
      for (std::size_t j = 0; j < sizeof(double); ++j)
        k[i * sizeof(double) + j] =
            static_cast<char>((std::bit_cast<std::uint64_t>(vals[i]) >> (8 * j)) & 0xffu);
    return k;
  }

  /// Measures every leaf of the call (last, last_index): the cached ones from the cache, the
  /// new ones in parallel on the current task arena (decompose calls the policy inside its
  /// arena, so madd_options::threads bounds it). Each measure is a pure function of the leaf,
  /// so the result does not depend on the schedule; when several fail, the error of the first
  /// leaf in order is thrown, as a sequential loop would.
  void measure_leaves(std::span<const madd_leaf_view> leaves) {
    std::vector<std::string> keys(leaves.size());
    std::vector<std::size_t> fresh; // leaves to measure, the first of each key
    std::unordered_map<std::string, std::size_t> fresh_key;
    for (std::size_t i = 0; i < leaves.size(); ++i) {
      keys[i] = key_of(leaves[i].loops.front(), leaves[i].area);
      if (!cache.contains(keys[i]) && fresh_key.emplace(keys[i], i).second) fresh.push_back(i);
    }
    std::vector<leaf_measure> measured(fresh.size());
    std::vector<std::exception_ptr> failed(fresh.size());
    parallel_ranges(fresh.size(), 1, [&](std::size_t first, std::size_t end) {
      for (std::size_t k = first; k != end; ++k)
        try {
          std::vector<std::vector<point>> loops;
          for (const auto& l : leaves[fresh[k]].loops)
            loops.emplace_back(l.begin(), l.end());
          measured[k] = measure(loops);
        } catch (...) {
          failed[k] = std::current_exception();
        }
    });
    for (const std::exception_ptr& e : failed)
      if (e) std::rethrow_exception(e);
    for (std::size_t k = 0; k < fresh.size(); ++k)
      cache.emplace(keys[fresh[k]], measured[k]);
    last.resize(leaves.size());
    last_index.clear();
    for (std::size_t i = 0; i < leaves.size(); ++i) {
      last[i] = cache.at(keys[i]);
      last_index.emplace(key_of(leaves[i].loops.front(), 0.0), i);
    }
  }

  /// The split policy: leaves failing Condition 3 always (Condition 3 alone always ends:
  /// the expected count shrinks with the area), leaves failing Condition 1 or 2 while they
  /// expect at least min_triangles (the termination rule for fields that no split can make
  /// acceptable, e.g. a jump of ratio > R2), and every leaf while fewer than min_leaves exist;
  /// priority: the expected triangles ("the largest subdomain first", size measured as
  /// work; the smallest positive double where nothing is expected).
  std::vector<double> operator()(std::span<const madd_leaf_view> leaves) {
    measure_leaves(leaves);
    const auto pairs = shared_edge_pairs(
        leaves.size(), [&](std::size_t i) -> const auto& { return leaves[i].loops; });
    std::vector<bool> whole(leaves.size());
    for (std::size_t i = 0; i < leaves.size(); ++i)
      whole[i] = leaves[i].keep_whole;
    last_fail = failed_conditions(last, pairs, r1, r2, t, whole);
    const bool few = leaves.size() < min_leaves;
    last_priority.assign(leaves.size(), 0.0);
    for (std::size_t i = 0; i < leaves.size(); ++i) {
      const unsigned f = last_fail[i];
      const bool want =
          (f & fails_condition_3) != 0u || (f != 0u && last[i].expected >= min_triangles) || few;
      if (want) last_priority[i] = std::max(last[i].expected, std::numeric_limits<double>::min());
    }
    return last_priority;
  }
};

} // namespace pdd::detail
