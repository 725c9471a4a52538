/// \file schedule_order.hpp
/// pdd::schedule_order: the order in which the executors start jobs (largest expected work
/// first), shared by the thread executors and pdd::mpi's master.
#pragma once

#include <pdd/core/index.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <span>
#include <vector>

namespace pdd {

/// Job indices in start order: decreasing expected work, ties by index (NaN counts as 0);
/// list scheduling in LPT order (dissertation 6.4, Algorithm 7.2 step 3: the subdomains
/// queued in reverse order of their expected mesh size). Complexity O(n log n).
inline std::vector<index_t> schedule_order(std::span<const double> work) {
  std::vector<index_t> order(work.size());
  std::iota(order.begin(), order.end(), index_t{0});
  auto w = [&](index_t i) { return std::isnan(work[i]) ? 0.0 : work[i]; };
  std::stable_sort(order.begin(), order.end(), [&](index_t a, index_t b) { return w(a) > w(b); });
  return order;
}

} // namespace pdd
