#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <thread>
#include <vector>

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/partitioner.h>
#include <oneapi/tbb/task_arena.h>

#if defined(__SANITIZE_THREAD__)
extern "C" void __tsan_acquire(void* address);
extern "C" void __tsan_release(void* address);
#endif

namespace zrender {

// oneTBB's scheduler is not built with ThreadSanitizer, which then cannot see that a task
// starts after the loop that spawned it and ends before the loop returns, nor that a thread
// takes a slot (Threads::slot()) only after the thread that had it left: these marks tell it
// (tools/tsan.sh). Nothing in other builds.
class TaskEdges {
 public:
#if defined(__SANITIZE_THREAD__)
  void spawn() {
    __tsan_release(&spawned_);
  }
  void begin() {
    __tsan_acquire(&spawned_);
  }
  void enter(void* slot) {
    __tsan_acquire(slot);
  }
  void end(void* slot) {
    __tsan_release(slot);
    __tsan_release(&ended_);
  }
  void join() {
    __tsan_acquire(&ended_);
  }

 private:
  char spawned_ = 0, ended_ = 0;
#else
  void spawn() {}
  void begin() {}
  void enter(void*) {}
  void end(void*) {}
  void join() {}
#endif
};

// The threads one renderer may use (docs/design.md, Threads): a oneTBB task arena of that
// many, or, for one thread, none at all: its loops then run in order on the calling thread,
// which is the single-threaded renderer exactly.
class Threads {
 public:
  explicit Threads(int count = 1);

  int count() const { return count_; }
  bool parallel() const { return count_ > 1; }
  // The index of the calling thread among the arena's, 0..count() - 1 (0 outside the arena,
  // and always 0 with one thread, even on a thread of another arena: a renderer of one thread
  // drawing a turntable's frame among others), to give each thread its own scratch.
  int slot() const;

  // Starts the arena's threads without waiting for them (an empty task), so that the first
  // loop finds them running. Nothing with one thread.
  void start() const {
    if (arena_) arena_->enqueue([] {});
  }

  // f() on the arena's threads (tbb's loops inside it use them), or with one thread on the
  // calling thread; f's exception is rethrown.
  template <typename F>
  void execute(const F& f) const {
    if (arena_)
      arena_->execute(f);
    else
      f();
  }

  // f(i) for every i in [0, n): with one thread, in increasing order on the calling thread;
  // with more, each index a task of the arena's, taken by whichever thread is free (tasks of
  // uneven cost balance).
  template <typename F>
  void forEach(size_t n, const F& f) const {
    if (!arena_) {
      for (size_t i = 0; i < n; ++i) f(i);
      return;
    }
    TaskEdges edges;
    edges.spawn();
    // Isolated: a thread waiting for this loop inside a task of another takes none of the
    // other's tasks, which would find the thread's scratch (by slot()) in use.
    arena_->execute([&] {
      tbb::this_task_arena::isolate([&] {
        tbb::parallel_for(
            tbb::blocked_range<size_t>(0, n, 1),
            [&](const tbb::blocked_range<size_t>& r) {
              edges.begin();
              void* slot = &slotMarks_[size_t(this->slot())];
              edges.enter(slot);
              for (size_t i = r.begin(); i < r.end(); ++i) f(i);
              edges.end(slot);
            },
            tbb::simple_partitioner());
      });
    });
    edges.join();
  }

  // f(order[k]) for every k: started in that order, each by whichever thread is free first. With
  // `order` sorted longest first, the threads end together as nearly as the tasks allow (a long
  // task started last ends last); forEach() lets the threads split the indices in halves.
  template <typename F>
  void forEachInOrder(const std::vector<uint32_t>& order, const F& f) const {
    std::atomic<size_t> next{0};
    forEach(size_t(count_), [&](size_t) {
      for (size_t k; (k = next.fetch_add(1, std::memory_order_relaxed)) < order.size();)
        f(size_t(order[k]));
    });
  }

  // f(begin, end) over [0, n) cut into ranges of about `grain` indices, spread over the
  // arena's threads (in order on the calling thread with one thread: f(0, n)).
  template <typename F>
  void forRanges(size_t n, size_t grain, const F& f) const {
    if (!arena_) {
      if (n > 0) f(size_t(0), n);
      return;
    }
    TaskEdges edges;
    edges.spawn();
    arena_->execute([&] {
      tbb::this_task_arena::isolate([&] {
        tbb::parallel_for(tbb::blocked_range<size_t>(0, n, grain),
                          [&](const tbb::blocked_range<size_t>& r) {
                            edges.begin();
                            void* slot = &slotMarks_[size_t(this->slot())];
                            edges.enter(slot);
                            f(r.begin(), r.end());
                            edges.end(slot);
                          });
      });
    });
    edges.join();
  }

 private:
  int count_;
  // oneTBB lets a process run as many threads as the machine has unless asked for more: a
  // request above that raises the limit while this object lives (the smallest of such
  // requests alive at once applies).
  std::unique_ptr<tbb::global_control> limit_;
  std::unique_ptr<tbb::task_arena> arena_;
  std::unique_ptr<char[]> slotMarks_;  // one address per slot, for TaskEdges
};

// Starts the arena of `threads` (Threads::start) from a thread of its own, joined when this
// goes out of scope: the caller goes on at once while oneTBB sets itself up and creates the
// arena's threads, which took 0.5 to 2 ms of the first loop of a process on this machine
// (docs/performance.md, Two threads, 2026-11-27 (second session)). Nothing with one thread.
class ThreadsStart {
 public:
  explicit ThreadsStart(const Threads& threads);
  ~ThreadsStart();
  ThreadsStart(const ThreadsStart&) = delete;
  ThreadsStart& operator=(const ThreadsStart&) = delete;

 private:
  std::thread thread_;
};

// The hardware threads of this machine (at least 1): the default of --threads.
int hardwareThreads();

}  // namespace zrender
