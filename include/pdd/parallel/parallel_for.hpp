/// \file parallel_for.hpp
/// Parallel loops over index ranges on oneTBB, used where the work is independent per index and
/// the result does not depend on the schedule.
///
/// Every pdd loop reaches TBB through parallel_ranges, whose task body is one short, fixed type
/// (range_body) and whose work is a std::function: when TBB got the callers' lambdas instead,
/// its task types carried the lambdas' types, which inside templates (a sizing field's lambda,
/// a test's lambda, a job of the executor) run to thousands of characters; ThreadSanitizer's
/// symbolizer then overflowed its buffer ("Symbolizer buffer too small") and a race report's
/// frames came out as `<null>`. One indirect call per range costs nothing measurable.
///
/// Nothing here speaks to ThreadSanitizer: the tsan preset links a libtbb built with
/// -fsanitize=thread (scripts/build-tsan-tbb.sh), which shows TBB's own fork, join and
/// work-stealing synchronisation to it, so no annotation or suppression stands between a race
/// and its report.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <cstddef>
#include <functional>
#include <utility>

namespace pdd::detail {

/// The work of one range: (first index, one past the last).
using range_function = std::function<void(std::size_t, std::size_t)>;

/// The task body TBB runs for every pdd loop (see the file comment).
struct range_body {
  const range_function* work;

  void operator()(const tbb::blocked_range<std::size_t>& r) const { (*work)(r.begin(), r.end()); }
};

/// How parallel_ranges cuts [0, n).
enum class range_split {
  balanced, ///< TBB's auto_partitioner: ranges of at least `grain` indices
  exact     ///< simple_partitioner: ranges of at most `grain` indices (1: one index a task)
};

/// Calls work(begin, end) for disjoint ranges covering [0, n), in parallel on the current
/// task arena. work must be safe to run concurrently on different ranges. Exceptions
/// propagate (TBB cancels the remaining ranges).
inline void parallel_ranges(std::size_t n, std::size_t grain, const range_function& work,
                            range_split split = range_split::balanced) {
  if (n == 0) return;
  const tbb::blocked_range<std::size_t> all(0, n, grain);
  if (split == range_split::exact)
    tbb::parallel_for(all, range_body{&work}, tbb::simple_partitioner{});
  else
    tbb::parallel_for(all, range_body{&work});
}

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
  const range_function each = [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i != end; ++i)
      f(i);
  };
  arena.execute([&] { parallel_ranges(n, 1, each); });
}

} // namespace pdd::detail

namespace pdd {

/// Runs f() with at most `threads` threads for everything it runs in parallel through oneTBB
/// (a tbb::task_arena of that concurrency; 0: TBB's default, f runs directly): a run asked for
/// one thread uses one, its checks and statistics included. Returns what f returns; exceptions
/// propagate. Thread-safe.
template <class F>
decltype(auto) with_threads(unsigned threads, F&& f) {
  if (threads == 0) return f();
  tbb::task_arena arena(static_cast<int>(threads));
  return arena.execute(std::forward<F>(f));
}

} // namespace pdd
