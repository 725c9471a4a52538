/// \file deterministic_reduce.hpp
/// A parallel reduction whose result is bitwise the same for every thread count: [0, n) is cut
/// into chunks whose bounds depend on n only, each chunk is accumulated on its own (in parallel),
/// and the chunks' results are joined in chunk order on the calling thread.
///
/// Why not tbb::parallel_deterministic_reduce: its task types carry the body's and the join's
/// types three times over; with lambdas inside templates (a sizing field's lambda, a test's
/// lambda) the symbolized names of its frames outgrew ThreadSanitizer's symbolizer buffer
/// ("Symbolizer buffer too small"), the frames came out as <null>, and the suppressions of TBB's
/// own task-object races (tests/tsan-suppressions.txt, matched by name) no longer applied. Here
/// the only type TBB instantiates is chunk_body, one short name for every caller.
#pragma once

#include <pdd/core/thread_sanitizer.hpp>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <vector>

namespace pdd::detail {

/// How [0, n) is cut: `count` chunks of `size` items (the last one shorter). Depends on n only.
struct chunk_plan {
  std::size_t n = 0;
  std::size_t size = 1;
  std::size_t count = 0;

  static constexpr std::size_t min_size = 4096;  ///< fewer items are not worth a task
  static constexpr std::size_t max_count = 1024; ///< bounds the memory of the partial results

  static chunk_plan of(std::size_t n) {
    chunk_plan p;
    p.n = n;
    p.size = std::max(min_size, (n + max_count - 1) / max_count);
    p.count = (n + p.size - 1) / p.size;
    return p;
  }
  std::size_t begin(std::size_t chunk) const { return chunk * size; }
  std::size_t end(std::size_t chunk) const { return std::min(n, (chunk + 1) * size); }
};

/// The signature of a chunk's work: (chunk index, first item, one past the last item).
using chunk_function = std::function<void(std::size_t, std::size_t, std::size_t)>;

/// The task body TBB runs: a fixed, short type (see the file comment).
struct chunk_body {
  const chunk_plan* plan;
  const chunk_function* work;
  const tsan_fork_join* fork_join;

  void operator()(const tbb::blocked_range<std::size_t>& chunks) const {
    tsan_fork_join::task_begins();
    const auto task = fork_join->task();
    for (std::size_t k = chunks.begin(); k != chunks.end(); ++k)
      (*work)(k, plan->begin(k), plan->end(k));
  }
};

/// Calls work(k, begin, end) for every chunk of the plan, in parallel on the current arena.
inline void for_each_chunk(const chunk_plan& plan, const chunk_function& work) {
  if (plan.count <= 1) {
    for (std::size_t k = 0; k < plan.count; ++k)
      work(k, plan.begin(k), plan.end(k));
    return;
  }
  const tsan_fork_join fork_join;
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, plan.count, 1),
                    chunk_body{&plan, &work, &fork_join});
  fork_join.join();
}

/// The reduction of [0, n): add_range(acc, begin, end) accumulates items into acc (which starts
/// as `identity`), join(into, from) folds from into into. Bitwise reproducible for any thread
/// count: the chunks and the order of the joins depend on n only.
template <class Acc, class AddRange, class Join>
Acc deterministic_reduce(std::size_t n, const Acc& identity, AddRange&& add_range, Join&& join) {
  const chunk_plan plan = chunk_plan::of(n);
  std::vector<Acc> partial(plan.count, identity);
  for_each_chunk(plan, [&](std::size_t k, std::size_t begin, std::size_t end) {
    add_range(partial[k], begin, end);
  });
  Acc total = identity;
  for (const Acc& p : partial)
    join(total, p);
  return total;
}

} // namespace pdd::detail
