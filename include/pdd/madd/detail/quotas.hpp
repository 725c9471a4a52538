/// \file quotas.hpp
/// Implementation detail of MADD into N subdomains: how many subdomains each region of the
/// split tree is to become (its quota), so that the largest subdomain stays close to the mean
/// at every N, not only at powers of two (issue 36 item 4).
///
/// Halving the largest region first gives, at N = 3 2^k, 2^k regions of twice the area of the
/// other 2^(k+1): largest/mean 1.5 with perfect splits and more with real ones (1.55-1.73
/// measured at N = 7 and 12). With quotas, a region that is to become q subdomains is split
/// with the target shares floor(q / 2) : ceil(q / 2), and before every round the N are shared
/// anew among the current regions by their areas (allot_quotas), so that a child left larger
/// than its share gets more: the partitioner's imbalance is corrected instead of compounded.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <queue>
#include <utility>
#include <vector>

namespace pdd::detail {

/// The quotas of two children of areas a0 and a1 that together become `quota` >= 2
/// subdomains: each at least 1, the larger area per subdomain as small as it can be (ties:
/// the smaller quota for child 0).
inline std::array<std::size_t, 2> child_quotas(double a0, double a1, std::size_t quota) {
  const auto worst = [&](std::size_t q0) { return std::max(a0 / q0, a1 / (quota - q0)); };
  const double ideal = static_cast<double>(quota) * a0 / (a0 + a1);
  const auto lo = static_cast<std::size_t>(std::clamp(ideal, 1.0, double(quota - 1)));
  std::size_t best = lo;
  if (lo + 1 <= quota - 1 && worst(lo + 1) < worst(lo)) best = lo + 1;
  return {best, quota - best};
}

/// The balance of a split of a region that is to become `quota` subdomains into children of
/// areas a0 and a1: the larger area per subdomain of the children (child_quotas) over the
/// region's area per subdomain, halved, so that for quota 2 it is the larger child's share
/// of the area (0.5: an even split). Compared with madd_options::imbalance_bound.
inline double split_balance(double a0, double a1, std::size_t quota) {
  if (quota < 2) quota = 2;
  const std::array<std::size_t, 2> q = child_quotas(a0, a1, quota);
  const double per_region = (a0 + a1) / static_cast<double>(quota);
  return 0.5 * std::max(a0 / static_cast<double>(q[0]), a1 / static_cast<double>(q[1])) /
         per_region;
}

/// Part 0's target share of a split into `quota` subdomains: floor(quota / 2) / quota (0.5 for
/// an even quota and for quota < 2).
inline double target_share(std::size_t quota) {
  if (quota < 2) return 0.5;
  return static_cast<double>(quota / 2) / static_cast<double>(quota);
}

/// Hands `extra` more subdomains to the regions open[i] (indices into areas and quotas), one at
/// a time to the one with the largest area per subdomain (ties: the lower index): the
/// apportionment that makes the largest area per subdomain smallest. O((|open| + extra) log).
inline void allot_quotas(const std::vector<double>& areas, std::vector<std::size_t>& quotas,
                         const std::vector<std::size_t>& open, std::size_t extra) {
  using entry = std::pair<double, std::size_t>; // area per subdomain, -index order via compare
  const auto less = [](const entry& a, const entry& b) {
    return a.first != b.first ? a.first < b.first : a.second > b.second;
  };
  std::priority_queue<entry, std::vector<entry>, decltype(less)> heap(less);
  for (const std::size_t i : open)
    heap.push({areas[i] / static_cast<double>(quotas[i]), i});
  for (; extra > 0 && !heap.empty(); --extra) {
    const std::size_t i = heap.top().second;
    heap.pop();
    ++quotas[i];
    heap.push({areas[i] / static_cast<double>(quotas[i]), i});
  }
}

} // namespace pdd::detail
