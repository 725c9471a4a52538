// The ThreadSanitizer stage's self-test (tsan preset only): two iterations of a pdd parallel
// loop, held on two threads at once, both write one int without synchronisation. ctest expects
// ThreadSanitizer's data race report in the output (PASS_REGULAR_EXPRESSION), so a stage that
// has stopped seeing races, through a lost -fsanitize=thread, a suppression or an annotation
// that orders the tasks, fails here instead of passing every parallel test unseen.
#include <pdd/parallel/parallel_for.hpp>

#include <atomic>
#include <chrono>
#include <cstdio>

namespace {

int shared_value = 0;

/// Spins until `flag` reaches `value` (relaxed: no happens-before) or 30 s pass.
bool wait_for(const std::atomic<int>& flag, int value) {
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (flag.load(std::memory_order_relaxed) < value)
    if (std::chrono::steady_clock::now() > give_up) return false;
  return true;
}

} // namespace

int main() {
  // Both iterations first meet (so they run on two threads at once), then write one after the
  // other: iteration 1 waits for iteration 0's write. Every flag is relaxed, which orders
  // nothing for ThreadSanitizer, so the two writes stay unordered; writing at the same instant
  // instead can slip past it (each thread checks the shadow before the other has set it).
  std::atomic<int> started{0}, written{0};
  std::atomic<bool> paired{true};
  pdd::detail::parallel_for_index(2, 2, [&](std::size_t i) {
    started.fetch_add(1, std::memory_order_relaxed);
    if (!wait_for(started, 2) || (i == 1 && !wait_for(written, 1))) {
      paired = false; // one thread ran both iterations: no race to see
      return;
    }
    shared_value += 1;
    if (i == 0) written.store(1, std::memory_order_relaxed);
  });
  std::printf("race_is_reported: %s, value %d\n",
              paired ? "two threads wrote one after the other" : "the iterations never met",
              shared_value);
  return paired ? 0 : 1;
}
