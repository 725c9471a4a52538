/// \file jobs.hpp
/// Implementation helpers shared by the executors: the start order of jobs and the
/// collection and rethrowing of job exceptions.
#pragma once

#include <pdd/core/index.hpp>

#include <algorithm>
#include <cmath>
#include <exception>
#include <numeric>
#include <span>
#include <vector>

namespace pdd::detail {

/// Job indices in start order: decreasing expected work, ties by index (NaN counts as 0).
/// Complexity O(n log n).
inline std::vector<index_t> schedule_order(std::span<const double> work) {
  std::vector<index_t> order(work.size());
  std::iota(order.begin(), order.end(), index_t{0});
  auto w = [&](index_t i) { return std::isnan(work[i]) ? 0.0 : work[i]; };
  std::stable_sort(order.begin(), order.end(), [&](index_t a, index_t b) { return w(a) > w(b); });
  return order;
}

/// One slot per job for the exception it threw; written by the job's own thread only.
class job_errors {
public:
  explicit job_errors(std::size_t n) : errors_(n) {}

  /// Runs job(i), storing any exception in slot i.
  template <class Job>
  void guarded(Job& job, index_t i) noexcept {
    try {
      job(i);
    } catch (...) {
      errors_[i] = std::current_exception();
    }
  }

  /// Rethrows the original exception of the smallest failing job (oneTBB's model: the caller
  /// catches what the job threw; whoever knows what a job index means adds it).
  void rethrow_first() const {
    for (const std::exception_ptr& e : errors_)
      if (e) std::rethrow_exception(e);
  }

private:
  std::vector<std::exception_ptr> errors_;
};

} // namespace pdd::detail
