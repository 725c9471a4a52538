/// \file parallel_for.hpp
/// A parallel loop over indices on a oneTBB arena of a given number of threads, used where the
/// work is independent per index and the result does not depend on the schedule.
#pragma once

#include <pdd/core/thread_sanitizer.hpp>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <cstddef>

namespace pdd::detail {

/// Calls f(i) for i in [0, n): sequentially when threads == 1 or n <= 1, otherwise on a
/// tbb::task_arena of `threads` threads (0: TBB's default). f must be safe to run concurrently
/// for different i. Exceptions propagate (TBB cancels the remaining iterations).
template <class F>
void parallel_for_index(std::size_t n, unsigned threads, F&& f) {
  if (threads == 1 || n <= 1) {
    for (std::size_t i = 0; i < n; ++i)
      f(i);
    return;
  }
  tbb::task_arena arena(threads == 0 ? tbb::task_arena::automatic : static_cast<int>(threads));
  const tsan_fork_join fork_join;
  arena.execute([&] {
    tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) {
      pdd::detail::tsan_fork_join::task_begins();
      const auto task = fork_join.task();
      f(i);
    });
  });
  fork_join.join();
}

} // namespace pdd::detail
