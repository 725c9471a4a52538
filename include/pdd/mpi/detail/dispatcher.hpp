/// \file dispatcher.hpp
/// Implementation of pdd::mpi::mesh_subdomains: the master/worker hand-out of jobs over the
/// ranks of a communicator (dissertation Algorithm 7.2), each rank running its jobs on its own
/// oneTBB threads.
#pragma once

#include <pdd/core/index.hpp>
#include <pdd/mpi/detail/wire.hpp>
#include <pdd/parallel/schedule_order.hpp>

#include <mpi.h>
#include <tbb/concurrent_queue.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstddef>
#include <span>
#include <vector>

namespace pdd::mpi::detail {

/// Message tags on the dispatcher's (private, duplicated) communicator.
enum dispatch_tag : int { tag_request = 1, tag_assign = 2 };

/// Hands jobs out over the ranks of `comm` (Algorithm 7.2). Rank 0 is the master: it keeps the
/// jobs in decreasing order of expected work (pdd::schedule_order) and answers every
/// request with the next job, or -1 when none is left. Every rank, rank 0 included, is a worker
/// with `threads` slots: its main thread asks for one job per free slot (rank 0 takes it from
/// the queue directly), runs each job it receives on its oneTBB arena, and asks again when a
/// job ends. Only the main thread calls MPI (MPI_THREAD_FUNNELED suffices); waiting threads
/// sleep rather than spin (backoff). The jobs must not throw.
class dispatcher {
public:
  dispatcher(MPI_Comm comm, unsigned threads)
      : comm_(comm), threads_(std::max(1u, threads)),
        // the arena's threads are all workers (the main thread stays outside, talking MPI)
        control_(tbb::global_control::max_allowed_parallelism, threads_ + 1),
        arena_(static_cast<int>(threads_), 0) {
    check(MPI_Comm_rank(comm_, &rank_), "MPI_Comm_rank");
  }

  /// Runs job(i) for every i in [0, work.size()) on exactly one rank, largest work first, and
  /// returns on every rank when all jobs of all ranks have ended. Collective: every rank passes
  /// the same work. \pre job(i) does not throw.
  template <class Job>
  void run(std::span<const double> work, Job& job) {
    if (rank_ == 0) order_ = pdd::schedule_order(work);
    next_ = 0;
    running_ = outstanding_ = 0;
    exhausted_ = false;
    backoff pause;
    while (!exhausted_ || running_ > 0 || outstanding_ > 0) {
      bool progress = ask_for_work(job);
      progress = receive_work(job) || progress;
      progress = serve_requests() || progress;
      progress = collect_finished() || progress;
      if (progress)
        pause.progress();
      else
        pause.idle();
    }
    // Every rank has received its last answer: once all are here, no request is left.
    MPI_Request barrier;
    check(MPI_Ibarrier(comm_, &barrier), "MPI_Ibarrier");
    wait_politely(barrier, [this] { return serve_requests(); });
  }

private:
  /// Master: the next job in order, or -1.
  long long next_job() {
    return next_ < order_.size() ? static_cast<long long>(order_[next_++]) : -1;
  }

  template <class Job>
  void start(Job& job, index_t i) {
    ++running_;
    arena_.enqueue([this, &job, i] {
      job(i);
      finished_.push(i);
    });
  }

  /// Fills the free slots: rank 0 from its queue, the others by asking rank 0.
  template <class Job>
  bool ask_for_work(Job& job) {
    bool any = false;
    while (!exhausted_ && running_ + outstanding_ < threads_) {
      any = true;
      if (rank_ == 0) {
        const long long i = next_job();
        if (i < 0)
          exhausted_ = true;
        else
          start(job, static_cast<index_t>(i));
      } else {
        const int one = 1;
        check(MPI_Send(&one, 1, MPI_INT, 0, tag_request, comm_), "MPI_Send");
        ++outstanding_;
      }
    }
    return any;
  }

  /// Worker: starts the jobs rank 0 sent.
  template <class Job>
  bool receive_work(Job& job) {
    if (rank_ == 0) return false;
    bool any = false;
    for (;;) {
      int arrived = 0;
      check(MPI_Iprobe(0, tag_assign, comm_, &arrived, MPI_STATUS_IGNORE), "MPI_Iprobe");
      if (!arrived) return any;
      long long i = -1;
      check(MPI_Recv(&i, 1, MPI_LONG_LONG, 0, tag_assign, comm_, MPI_STATUS_IGNORE), "MPI_Recv");
      --outstanding_;
      any = true;
      if (i < 0)
        exhausted_ = true;
      else
        start(job, static_cast<index_t>(i));
    }
  }

  /// Master: answers every pending request with the next job (Algorithm 7.2 step 5).
  bool serve_requests() {
    if (rank_ != 0) return false;
    bool any = false;
    for (;;) {
      int arrived = 0;
      MPI_Status status;
      check(MPI_Iprobe(MPI_ANY_SOURCE, tag_request, comm_, &arrived, &status), "MPI_Iprobe");
      if (!arrived) return any;
      int one = 0;
      check(MPI_Recv(&one, 1, MPI_INT, status.MPI_SOURCE, tag_request, comm_, MPI_STATUS_IGNORE),
            "MPI_Recv");
      const long long i = next_job();
      check(MPI_Send(&i, 1, MPI_LONG_LONG, status.MPI_SOURCE, tag_assign, comm_), "MPI_Send");
      any = true;
    }
  }

  bool collect_finished() {
    bool any = false;
    for (index_t i; finished_.try_pop(i);) {
      --running_;
      any = true;
    }
    return any;
  }

  MPI_Comm comm_;
  int rank_ = 0;
  unsigned threads_;
  tbb::global_control control_;
  tbb::task_arena arena_;
  tbb::concurrent_queue<index_t> finished_;
  std::vector<index_t> order_; // master: the jobs in start order
  std::size_t next_ = 0;       // master: the next position in order_
  unsigned running_ = 0, outstanding_ = 0;
  bool exhausted_ = false;
};

} // namespace pdd::mpi::detail
