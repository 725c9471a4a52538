/// \file deterministic_reduce.hpp
/// A parallel reduction whose result is bitwise the same for every thread count: [0, n) is cut
/// into chunks whose bounds depend on n only, each chunk is accumulated on its own (in parallel,
/// through parallel_ranges), and the chunks' results are joined in chunk order on the calling
/// thread. (tbb::parallel_deterministic_reduce would do the same, but its task types carry the
/// body's and the join's types: see parallel_for.hpp on why pdd's loops avoid that.)
#pragma once

#include <pdd/parallel/parallel_for.hpp>

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

/// Calls work(k, begin, end) for every chunk of the plan, in parallel on the current arena.
inline void for_each_chunk(const chunk_plan& plan, const chunk_function& work) {
  parallel_ranges(plan.count, 1, [&](std::size_t first, std::size_t last) {
    for (std::size_t k = first; k != last; ++k)
      work(k, plan.begin(k), plan.end(k));
  });
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
