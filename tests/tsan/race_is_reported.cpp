// The ThreadSanitizer stage's self-test (tsan preset only): two iterations of a pdd parallel
// loop, held on two threads at once, both write one int without synchronisation. ctest expects
// ThreadSanitizer's data race report in the output (PASS_REGULAR_EXPRESSION), so a stage that
// has stopped seeing races, through a lost -fsanitize=thread, a suppression or an annotation
// that orders the tasks, fails here instead of passing every parallel test unseen.
#include <pdd/parallel/parallel_for.hpp>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <thread>

namespace {

int shared_value = 0;

} // namespace

int main() {
  std::atomic<int> started{0};
  bool paired = true;
  pdd::detail::parallel_for_index(2, 2, [&](std::size_t) {
    // relaxed: the counter orders nothing, so ThreadSanitizer sees two unordered writes
    started.fetch_add(1, std::memory_order_relaxed);
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (started.load(std::memory_order_relaxed) < 2)
      if (std::chrono::steady_clock::now() > give_up) {
        paired = false; // one thread ran both iterations: no race to see
        return;
      }
    shared_value += 1;
  });
  std::printf("race_is_reported: %s, value %d\n",
              paired ? "two threads wrote at once" : "the iterations never met", shared_value);
  return paired ? 0 : 1;
}
