// Tests of the executors (dissertation 6.4): every job runs once, in order of decreasing
// expected work on one thread, concurrently on several, and a failing job's original exception
// reaches the caller after all jobs ran.
#include <pdd/errors.hpp>
#include <pdd/parallel/sequential_executor.hpp>
#include <pdd/parallel/tbb_executor.hpp>

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

namespace executors_test {
namespace {

using pdd::index_t;

/// An exception that is not a pdd::error, carrying the index of the job that threw it.
struct job_failure : std::runtime_error {
  explicit job_failure(index_t i) : std::runtime_error("job failure"), job(i) {}
  index_t job;
};

template <class E>
void check_executor(const E& ex) {
  const std::vector<double> work{1, 5, 3, 5, 0, 2};
  std::vector<std::atomic<int>> runs(work.size());
  std::mutex m;
  std::vector<index_t> started;
  ex.run(work, [&](index_t i) {
    ++runs[i];
    const std::lock_guard lock(m);
    started.push_back(i);
  });
  for (auto& r : runs)
    EXPECT_EQ(r.load(), 1);
  if (ex.concurrency() == 1) {
    EXPECT_EQ(started, (std::vector<index_t>{1, 3, 2, 5, 0, 4}));
  }
  // Errors: all jobs still run; the original exception of the smallest failing index comes
  // out, of its own type and unwrapped (job 2 starts after job 4 in the start order).
  for (int repeat = 0; repeat < 20; ++repeat) {
    std::atomic<int> count{0};
    try {
      ex.run(work, [&](index_t i) {
        ++count;
        if (i == 4) throw job_failure(4);
        if (i == 2) throw job_failure(2);
      });
      FAIL() << "no exception";
    } catch (const job_failure& e) {
      EXPECT_EQ(e.job, 2u);
      EXPECT_STREQ(e.what(), "job failure");
    }
    EXPECT_EQ(count.load(), 6);
  }
  // A pdd error passes unchanged, its type and data intact.
  try {
    ex.run(work, [&](index_t i) {
      if (i == 3) throw pdd::meshing_error(42, "inner");
      if (i == 5) throw pdd::geometry_error("later", {7});
    });
    FAIL() << "no exception";
  } catch (const pdd::meshing_error& e) {
    EXPECT_EQ(e.subdomain(), 42);
    EXPECT_STREQ(e.what(), "subdomain 42: inner");
  }
  ex.run(std::vector<double>{}, [](index_t) { FAIL(); });
}

TEST(Executors, SequentialOrderAndErrors) {
  check_executor(pdd::sequential_executor{});
}
TEST(Executors, TbbOneThread) {
  EXPECT_EQ(pdd::tbb_executor{1}.concurrency(), 1u);
  check_executor(pdd::tbb_executor{1});
}
TEST(Executors, TbbTwoAndFourThreads) {
  check_executor(pdd::tbb_executor{2});
  check_executor(pdd::tbb_executor{4});
  EXPECT_GE(pdd::tbb_executor{}.concurrency(), 1u);
}
/// Runs two jobs on `ex`, each of which announces that it started and then waits (up to
/// `timeout`) for the other to have started too. Returns how many jobs met the other: 2 only
/// when both ran at once; run one after the other, the first times out before the second
/// starts (a barrier that sequential execution can never pass).
template <class Executor>
int jobs_that_met(const Executor& ex, std::chrono::milliseconds timeout) {
  std::atomic<int> started{0}, met{0};
  ex.run(std::vector<double>{1, 1}, [&](index_t) {
    started.fetch_add(1);
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (started.load() < 2 && std::chrono::steady_clock::now() < deadline)
      std::this_thread::yield();
    if (started.load() == 2) met.fetch_add(1);
  });
  return met.load();
}

TEST(Executors, TbbRunsConcurrently) {
  for (int round = 0; round < 3; ++round)
    ASSERT_EQ(jobs_that_met(pdd::tbb_executor{2}, std::chrono::seconds(30)), 2)
        << "round " << round << ": the two jobs did not run at once";
}

TEST(Executors, ConcurrencyCheckFailsForSequentialJobs) {
  // The check of TbbRunsConcurrently can fail: jobs run one after the other meet once.
  EXPECT_EQ(jobs_that_met(pdd::sequential_executor{}, std::chrono::milliseconds(50)), 1);
  EXPECT_EQ(jobs_that_met(pdd::tbb_executor{1}, std::chrono::milliseconds(50)), 1);
}

} // namespace

} // namespace executors_test
