/// \file tbb_executor.hpp
/// pdd::tbb_executor: runs the jobs on a oneTBB task arena of a given number of threads.
#pragma once

#include <pdd/concepts/executor.hpp>
#include <pdd/parallel/detail/jobs.hpp>
#include <pdd/parallel/parallel_for.hpp>
#include <pdd/parallel/schedule_order.hpp>

#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <span>

namespace pdd {

/// Models Executor with oneTBB: a `tbb::task_arena` of `threads` threads (0: all cores, TBB's
/// default concurrency) whose workers take jobs from one shared queue in order of decreasing
/// expected work (dynamic list scheduling: a worker that finishes a job takes the largest job
/// not yet started; dissertation 6.4 balances by over-decomposition and area).
/// Thread-safety: const; each run() creates its own arena.
struct tbb_executor {
  unsigned threads = 0; ///< 0: all cores

  /// The number of threads run() uses.
  unsigned concurrency() const {
    return threads > 0
               ? threads
               : static_cast<unsigned>(std::max(1, tbb::this_task_arena::max_concurrency()));
  }

  /// Runs job(i) for every i in [0, work.size()), starting them in order of decreasing work[i].
  /// \throws the original exception of the smallest failing index, after all jobs ran (see
  /// the Executor concept). Complexity: n log n plus the jobs.
  template <class Job>
  void run(std::span<const double> work, Job&& job) const {
    const std::size_t n = work.size();
    if (n == 0) return;
    const std::vector<index_t> order = schedule_order(work);
    detail::job_errors errors(n);
    const unsigned p = concurrency();
    if (p == 1 || n == 1) {
      for (const index_t i : order)
        errors.guarded(job, i);
    } else {
      tbb::task_arena arena(static_cast<int>(p));
      std::atomic<std::size_t> next{0};
      const std::size_t workers = std::min<std::size_t>(p, n);
      // one task per worker, each taking the next job in schedule order until none is left
      const detail::range_function take_jobs = [&](std::size_t, std::size_t) {
        for (std::size_t pos; (pos = next.fetch_add(1, std::memory_order_relaxed)) < n;)
          errors.guarded(job, order[pos]);
      };
      arena.execute(
          [&] { detail::parallel_ranges(workers, 1, take_jobs, detail::range_split::exact); });
    }
    errors.rethrow_first();
  }
};
static_assert(Executor<tbb_executor>);

} // namespace pdd
