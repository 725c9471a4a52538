/// \file thread_sanitizer.hpp
/// Makes the fork and join of a oneTBB parallel construct visible to ThreadSanitizer.
///
/// oneTBB synchronises the spawning thread with its workers inside libtbb; a libtbb that is not
/// built with -fsanitize=thread (Debian's) hides that synchronisation from ThreadSanitizer, which
/// then reports every result a worker wrote and the caller reads after the construct as a data
/// race (google/sanitizers#1004, oneTBB#358: "rebuild TBB with TSan"). pdd states the two
/// happens-before edges TBB guarantees, and only those: the caller's work before the construct
/// happens before every task (fork), and every task happens before the caller's work after it
/// (join). Tasks are not ordered among themselves, so races between tasks are still reported.
/// Without ThreadSanitizer every member is an empty inline function.
#pragma once

#if defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define PDD_THREAD_SANITIZER 1
#endif
#endif
#if !defined(PDD_THREAD_SANITIZER) && defined(__SANITIZE_THREAD__)
#define PDD_THREAD_SANITIZER 1
#endif

#ifdef PDD_THREAD_SANITIZER
extern "C" void __tsan_acquire(void* addr);
extern "C" void __tsan_release(void* addr);
#endif

namespace pdd::detail {

/// One parallel construct's fork and join edges. Construct it right before the construct, open
/// a task_scope at the start of every task body (and reduction join), call join() after it.
class tsan_fork_join {
public:
  tsan_fork_join() {
    release(&fork_);
    release(&any_fork());
  }

  /// The first statement of every task body, before it reads anything its closure captured:
  /// the closure lives on the caller's stack and a task reads it before it can reach this
  /// object's own fork edge, so the fork is also released on one process-wide address that a
  /// task acquires without reading its closure (a stack slot reused by the caller before the
  /// construct was otherwise reported as a race). Tasks never release it, so it orders no two
  /// tasks.
  static void task_begins() { acquire(&any_fork()); }
  tsan_fork_join(const tsan_fork_join&) = delete;
  tsan_fork_join& operator=(const tsan_fork_join&) = delete;

  /// Marks one task body: it starts after the fork and ends before the join.
  class task_scope {
  public:
    explicit task_scope(const tsan_fork_join& fj) : fj_(fj) { acquire(&fj_.fork_); }
    ~task_scope() { release(&fj_.join_); }
    task_scope(const task_scope&) = delete;
    task_scope& operator=(const task_scope&) = delete;

  private:
    const tsan_fork_join& fj_;
  };

  task_scope task() const { return task_scope(*this); }
  /// After the construct returned: every task happened before what follows.
  void join() const { acquire(&join_); }

private:
#ifdef PDD_THREAD_SANITIZER
  static void acquire(const void* a) {
    __tsan_acquire(const_cast<void*>(a));
  }
  static void release(const void* a) {
    __tsan_release(const_cast<void*>(a));
  }
#else
  static void acquire(const void*) {}
  static void release(const void*) {}
#endif
  static char& any_fork() {
    static char address = 0;
    return address;
  }
  char fork_ = 0;
  mutable char join_ = 0;
};

} // namespace pdd::detail
