/// \file sequential_executor.hpp
/// pdd::sequential_executor: runs the jobs one after another on the calling thread.
#pragma once

#include <pdd/concepts/executor.hpp>
#include <pdd/parallel/detail/jobs.hpp>
#include <pdd/parallel/schedule_order.hpp>

#include <span>

namespace pdd {

/// Models Executor on the calling thread: jobs run one at a time, largest expected work first.
/// Thread-safety: const; run() may be called from several threads at once.
struct sequential_executor {
  /// Always 1.
  unsigned concurrency() const noexcept { return 1; }

  /// Runs job(i) for every i in [0, work.size()) in order of decreasing work[i].
  /// \throws the original exception of the smallest failing index, after all jobs ran (see
  /// the Executor concept). Complexity: n log n plus the jobs.
  template <class Job>
  void run(std::span<const double> work, Job&& job) const {
    detail::job_errors errors(work.size());
    for (const index_t i : schedule_order(work))
      errors.guarded(job, i);
    errors.rethrow_first();
  }
};
static_assert(Executor<sequential_executor>);

} // namespace pdd
