#pragma once

#include <cstddef>
#include <memory>

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/global_control.h>
#include <oneapi/tbb/parallel_for.h>
#include <oneapi/tbb/partitioner.h>
#include <oneapi/tbb/task_arena.h>

namespace zrender {

// The threads one renderer may use (docs/design.md, Threads): a oneTBB task arena of that
// many, or, for one thread, none at all: its loops then run in order on the calling thread,
// which is the single-threaded renderer exactly.
class Threads {
 public:
  explicit Threads(int count = 1);

  int count() const { return count_; }
  bool parallel() const { return count_ > 1; }
  // The index of the calling thread among the arena's, 0..count() - 1 (0 outside the arena),
  // to give each thread its own scratch.
  int slot() const;

  // f(i) for every i in [0, n): with one thread, in increasing order on the calling thread;
  // with more, each index a task of the arena's, taken by whichever thread is free (tasks of
  // uneven cost balance).
  template <typename F>
  void forEach(size_t n, const F& f) const {
    if (!arena_) {
      for (size_t i = 0; i < n; ++i) f(i);
      return;
    }
    arena_->execute([&] {
      tbb::parallel_for(
          tbb::blocked_range<size_t>(0, n, 1),
          [&](const tbb::blocked_range<size_t>& r) {
            for (size_t i = r.begin(); i < r.end(); ++i) f(i);
          },
          tbb::simple_partitioner());
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
    arena_->execute([&] {
      tbb::parallel_for(tbb::blocked_range<size_t>(0, n, grain),
                        [&](const tbb::blocked_range<size_t>& r) { f(r.begin(), r.end()); });
    });
  }

 private:
  int count_;
  // oneTBB lets a process run as many threads as the machine has unless asked for more: a
  // request above that raises the limit while this object lives (the smallest of such
  // requests alive at once applies).
  std::unique_ptr<tbb::global_control> limit_;
  std::unique_ptr<tbb::task_arena> arena_;
};

// The hardware threads of this machine (at least 1): the default of --threads.
int hardwareThreads();

}  // namespace zrender
