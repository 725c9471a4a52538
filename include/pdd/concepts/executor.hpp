/// \file executor.hpp
/// The Executor concept: runs N independent jobs, largest expected work first.
///
/// Requirements: for `const E e`, a `std::span<const double> w` and a callable `job` with
/// `job(index_t)`, `e.run(w, job)` runs `job(i)` once for every `i` in `[0, w.size())` and
/// returns when all have finished; `e.concurrency()` is the number of jobs that may run at once.
///
/// Semantics (dissertation 6.4, static load balance by over-decomposition): jobs are *started*
/// in order of decreasing expected work `w[i]` (ties: smaller index first), so the largest
/// subdomains never end up last on an otherwise idle machine (list scheduling, LPT order).
/// Jobs may run concurrently on different threads; each job runs on one thread. If jobs throw,
/// every job still runs (so that the reported error does not depend on timing), and then the
/// exception of the smallest failing index is rethrown as it was thrown (std::exception_ptr,
/// oneTBB's model; the caller, who knows what index i stands for, adds that to the message).
/// The executor is const and may be shared.
///
/// Models: pdd::sequential_executor, pdd::tbb_executor.
#pragma once

#include <pdd/core/point.hpp>

#include <concepts>
#include <span>

namespace pdd {

namespace detail {
/// A job type used only to state the Executor concept.
struct executor_probe_job {
  void operator()(index_t) const {}
};
} // namespace detail

template <class E>
concept Executor = requires(const E& e, std::span<const double> work,
                            const detail::executor_probe_job& job) {
  e.run(work, job);
  { e.concurrency() } -> std::convertible_to<unsigned>;
};

} // namespace pdd
