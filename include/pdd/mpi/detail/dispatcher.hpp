/// \file dispatcher.hpp
/// Implementation of pdd::mpi::mesh_subdomains: the master/worker hand-out of jobs over the
/// ranks of a communicator (dissertation Algorithm 7.2), each rank running its jobs on its own
/// oneTBB threads.
#pragma once

#include <pdd/core/index.hpp>
#include <pdd/errors.hpp>
#include <pdd/mpi/detail/wire.hpp>
#include <pdd/parallel/schedule_order.hpp>

#include <mpi.h>
#include <tbb/concurrent_queue.h>
#include <tbb/global_control.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace pdd::mpi::detail {

/// Message tags on the dispatcher's (private, duplicated) communicator.
enum dispatch_tag : int { tag_request = 1, tag_assign = 2, tag_done = 3 };

/// Hands jobs out over the ranks of `comm` (Algorithm 7.2). Rank 0 is the master: it keeps the
/// jobs in decreasing order of expected work (pdd::schedule_order) and answers every
/// request with the next job, or -1 when none is left. Every rank, rank 0 included, is a worker
/// with `threads` slots: its main thread asks for one job per free slot (rank 0 takes it from
/// the queue directly), runs each job it receives on its oneTBB arena, and asks again when a
/// job ends. A job returns its report (bytes, possibly empty): every rank sends it to the master
/// when the job ends, where the master's main thread hands it to done(i, report) as it arrives
/// (a resumed run's manifest, issue 40); the master returns only once every job's report has
/// arrived. Only the main thread calls MPI (MPI_THREAD_FUNNELED suffices); waiting threads
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

  /// Runs job(i) (returning its report, a std::string) for every i in [0, work.size()) on
  /// exactly one rank, largest work first, calls done(i, report) on the master for each as its
  /// report arrives, and returns on every rank when all jobs of all ranks have ended. Collective:
  /// every rank passes the same work. \pre job(i) and done do not throw.
  template <class Job, class Done>
  void run(std::span<const double> work, Job& job, Done& done) {
    if (rank_ == 0) order_ = pdd::schedule_order(work);
    next_ = 0;
    running_ = outstanding_ = 0;
    remote_ = reported_ = 0;
    exhausted_ = false;
    backoff pause;
    while (!exhausted_ || running_ > 0 || outstanding_ > 0 || reported_ < remote_) {
      bool progress = ask_for_work(job);
      progress = receive_work(job) || progress;
      progress = serve_requests() || progress;
      progress = receive_reports(done) || progress;
      progress = collect_finished(done) || progress;
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
    arena_.enqueue([this, &job, i] { finished_.push({i, job(i)}); });
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
      remote_ += i >= 0;
      any = true;
    }
  }

  /// Master: hands every report that has arrived to done(i, report).
  template <class Done>
  bool receive_reports(Done& done) {
    if (rank_ != 0) return false;
    bool any = false;
    for (;;) {
      int arrived = 0, size = 0;
      MPI_Status status;
      check(MPI_Iprobe(MPI_ANY_SOURCE, tag_done, comm_, &arrived, &status), "MPI_Iprobe");
      if (!arrived) return any;
      check(MPI_Get_count(&status, MPI_BYTE, &size), "MPI_Get_count");
      std::string bytes(static_cast<std::size_t>(size), '\0');
      check(MPI_Recv(bytes.data(), size, MPI_BYTE, status.MPI_SOURCE, tag_done, comm_,
                     MPI_STATUS_IGNORE),
            "MPI_Recv");
      index_t i = 0;
      if (bytes.size() < sizeof i) throw internal_error("pdd::mpi: truncated job report");
      std::memcpy(&i, bytes.data(), sizeof i);
      done(i, std::string_view(bytes).substr(sizeof i));
      ++reported_;
      any = true;
    }
  }

  /// The jobs that ended: the master hands their reports to done, a worker sends them to it.
  template <class Done>
  bool collect_finished(Done& done) {
    bool any = false;
    for (std::pair<index_t, std::string> f; finished_.try_pop(f);) {
      --running_;
      any = true;
      if (rank_ == 0) {
        done(f.first, std::string_view(f.second));
        continue;
      }
      std::string bytes(sizeof f.first, '\0');
      std::memcpy(bytes.data(), &f.first, sizeof f.first);
      bytes += f.second;
      check(MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, 0, tag_done, comm_),
            "MPI_Send");
    }
    return any;
  }

  MPI_Comm comm_;
  int rank_ = 0;
  unsigned threads_;
  tbb::global_control control_;
  tbb::task_arena arena_;
  tbb::concurrent_queue<std::pair<index_t, std::string>> finished_; // jobs and their reports
  std::vector<index_t> order_; // master: the jobs in start order
  std::size_t next_ = 0;       // master: the next position in order_
  unsigned running_ = 0, outstanding_ = 0;
  std::size_t remote_ = 0, reported_ = 0; // master: jobs sent to workers, reports received
  bool exhausted_ = false;
};

} // namespace pdd::mpi::detail
