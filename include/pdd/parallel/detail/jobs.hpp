/// \file jobs.hpp
/// Implementation helpers shared by the executors: the collection and rethrowing of job
/// exceptions (the start order is pdd::schedule_order).
#pragma once

#include <pdd/core/index.hpp>

#include <exception>
#include <vector>

namespace pdd::detail {

/// One slot per job for the exception it threw; written by the job's own thread only.
class job_errors {
public:
  explicit job_errors(std::size_t n) : errors_(n) {}

  /// Runs job(i), storing any exception in slot i.
  template <class Job>
  void guarded(Job& job, index_t i) noexcept {
    try {
      job(i);
    } catch (...) {
      errors_[i] = std::current_exception();
    }
  }

  /// Rethrows the original exception of the smallest failing job (oneTBB's model: the caller
  /// catches what the job threw; whoever knows what a job index means adds it).
  void rethrow_first() const {
    for (const std::exception_ptr& e : errors_)
      if (e) std::rethrow_exception(e);
  }

private:
  std::vector<std::exception_ptr> errors_;
};

} // namespace pdd::detail
