/// \file fm.hpp
/// Implementation detail of the partitioners: Fiduccia–Mattheyses refinement of a bisection
/// under a balance bound (C. M. Fiduccia, R. M. Mattheyses, "A linear-time heuristic for
/// improving network partitions", DAC 1982), with real-valued gains kept in ordered sets.
#pragma once

#include <pdd/partition/detail/csr.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <set>
#include <utility>
#include <vector>

namespace pdd::detail {

/// Highest gain first; equal gains by vertex index, so every choice is deterministic.
struct fm_gain_order {
  bool operator()(const std::pair<double, std::size_t>& a,
                  const std::pair<double, std::size_t>& b) const {
    return a.first != b.first ? a.first > b.first : a.second < b.second;
  }
};

/// One FM pass: moves unlocked vertices one at a time, best gain first, keeping both parts
/// non-empty and the excess over the balance bound from growing (a balanced state may step to
/// an excess of at most one heaviest vertex); stops after stall_limit moves without a better
/// (excess, cut) and rolls back to the best prefix. O((n + m) log n).
class fm_pass {
public:
  fm_pass(const ml_graph& g, std::vector<std::uint8_t>& part, const part_limits& limits)
      : g_(g), part_(part), limits_(limits), gain_(boost::num_vertices(g), 0.0),
        locked_(boost::num_vertices(g), 0) {
    cut_ = ml_cut(g, part);
    for (std::size_t v = 0; v < boost::num_vertices(g); ++v) {
      slack_ = std::max(slack_, g[v].weight);
      w_[part[v]] += g[v].weight;
      ++count_[part[v]];
      for (const auto e : boost::make_iterator_range(boost::out_edges(v, g)))
        gain_[v] += part[boost::target(e, g)] == part[v] ? -g[e].weight : g[e].weight;
      queue_[part[v]].insert({gain_[v], v});
    }
  }

  void run(std::size_t stall_limit) {
    bisection_score best{balance_excess(w_, limits_), cut_};
    std::size_t best_length = 0, stalled = 0;
    while (stalled < stall_limit) {
      const auto c0 = candidate(0), c1 = candidate(1);
      if (!c0 && !c1) break;
      std::size_t v = c0 ? *c0 : *c1;
      if (c0 && c1 && fm_gain_order{}({gain_[*c1], *c1}, {gain_[*c0], *c0})) v = *c1;
      move(v);
      const bisection_score s{balance_excess(w_, limits_), cut_};
      if (s < best) {
        best = s;
        best_length = moves_.size();
        stalled = 0;
      } else {
        ++stalled;
      }
    }
    for (std::size_t i = moves_.size(); i > best_length; --i)
      part_[moves_[i - 1]] ^= 1U;
  }

private:
  using gain_queue = std::set<std::pair<double, std::size_t>, fm_gain_order>;
  static constexpr std::size_t scan_limit = 8;

  // The best-gain vertex of `side` among the first few whose move keeps the excess within the
  // limit: from a balanced state up to one heaviest vertex (so that FM can step through
  // unbalanced states when the bound is tight, e.g. exact halves), else no growth at all.
  std::optional<std::size_t> candidate(int side) const {
    if (count_[side] < 2) return std::nullopt;
    const double excess = balance_excess(w_, limits_);
    const double now = excess > 0.0 ? excess : slack_;
    std::size_t scanned = 0;
    for (const auto& [gain, v] : queue_[side]) {
      const double vw = g_[v].weight;
      std::array<double, 2> after = w_;
      after[side] -= vw;
      after[1 - side] += vw;
      if (balance_excess(after, limits_) <= now) return v;
      if (++scanned == scan_limit) break;
    }
    return std::nullopt;
  }

  void move(std::size_t v) {
    const int from = part_[v], to = 1 - from;
    queue_[from].erase({gain_[v], v});
    locked_[v] = 1;
    cut_ -= gain_[v];
    w_[from] -= g_[v].weight;
    w_[to] += g_[v].weight;
    --count_[from];
    ++count_[to];
    part_[v] = static_cast<std::uint8_t>(to);
    moves_.push_back(v);
    for (const auto e : boost::make_iterator_range(boost::out_edges(v, g_))) {
      const std::size_t t = boost::target(e, g_);
      if (locked_[t]) continue;
      queue_[part_[t]].erase({gain_[t], t});
      gain_[t] += part_[t] == to ? -2.0 * g_[e].weight : 2.0 * g_[e].weight;
      queue_[part_[t]].insert({gain_[t], t});
    }
  }

  const ml_graph& g_;
  std::vector<std::uint8_t>& part_;
  part_limits limits_;
  std::vector<double> gain_;
  std::vector<char> locked_;
  std::array<gain_queue, 2> queue_;
  std::array<double, 2> w_{0.0, 0.0};
  std::array<std::size_t, 2> count_{0, 0};
  double cut_ = 0.0;
  double slack_ = 0.0; // the heaviest vertex
  std::vector<std::size_t> moves_;
};

/// Moves without improvement after which an FM pass gives up.
inline std::size_t fm_stall_limit(std::size_t n) {
  return std::clamp<std::size_t>(n / 10, 30, 300);
}

/// FM passes until one fails to lower the (excess, cut) score, at most max_passes. The result
/// never scores worse than the input (scores are recomputed exactly after each pass).
/// \pre part has two non-empty sides when g has >= 2 vertices. Returns the final score.
inline bisection_score fm_refine(const ml_graph& g, std::vector<std::uint8_t>& part,
                                 const part_limits& limits, int max_passes) {
  bisection_score current = score_bisection(g, part, limits);
  if (boost::num_vertices(g) < 2) return current;
  for (int pass = 0; pass < max_passes; ++pass) {
    std::vector<std::uint8_t> before = part;
    fm_pass(g, part, limits).run(fm_stall_limit(boost::num_vertices(g)));
    const bisection_score after = score_bisection(g, part, limits);
    if (!(after < current)) {
      part = std::move(before);
      break;
    }
    current = after;
  }
  return current;
}

} // namespace pdd::detail
