/// \file deterministic_reduce.hpp
/// A parallel fold over indices whose result does not depend on the thread count: oneTBB's
/// parallel_deterministic_reduce splits and joins [0, n) the same way for any number of threads,
/// so a floating-point sum comes out with the same bits on 1 or 64 threads. The fork and join
/// are stated for ThreadSanitizer (core/thread_sanitizer.hpp).
#pragma once

#include <pdd/core/thread_sanitizer.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <cstddef>

namespace pdd::detail {

/// The accumulator of [0, n): add(acc, i) for every i in a range, starting from Acc{} per
/// range, and a.join(b) to combine two neighbouring ranges (a left of b). `grain` fixes the
/// split tree (with the range, all it depends on). add must be safe to run concurrently on
/// different accumulators. \tparam Acc default-constructible, with join(const Acc&).
template <class Acc, class Add>
Acc deterministic_reduce(std::size_t n, std::size_t grain, const Add& add) {
  using range = tbb::blocked_range<std::size_t>;
  const tsan_fork_join fork_join;
  const auto body = [&](const range& r, Acc acc) {
    tsan_fork_join::task_begins();
    const auto task = fork_join.task();
    for (std::size_t i = r.begin(); i != r.end(); ++i)
      add(acc, i);
    return acc;
  };
  const auto join = [&](Acc a, const Acc& b) {
    tsan_fork_join::task_begins();
    const auto task = fork_join.task();
    a.join(b);
    return a;
  };
  Acc acc = tbb::parallel_deterministic_reduce(range(0, n, grain), Acc{}, body, join);
  fork_join.join();
  return acc;
}

} // namespace pdd::detail
