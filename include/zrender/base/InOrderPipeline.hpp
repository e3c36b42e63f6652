#pragma once

#include <cstddef>
#include <memory>

#include <oneapi/tbb/parallel_pipeline.h>

#include "zrender/base/Threads.hpp"

namespace zrender {

// Items 0..n-1 in two stages on `threads` (docs/design.md, Threads: a turntable's frames at
// once): work(i, slot) on whichever thread is free, at most `slots` items at once, then
// finish(i, slot) one item at a time in increasing i, on any thread. `slot` is i % slots: state
// the caller keeps per slot (a renderer) is free when item i's work starts, since item
// i - slots has finished. With one thread or one slot, work(i, 0) then finish(i, 0) on the
// calling thread, item after item. An exception stops the items not yet started and the first
// thrown is rethrown once those running have ended. `work` must not wait for other tasks of
// `threads`' arena (a thread waiting would take another item's work).
template <typename Work, typename Finish>
void pipelineInOrder(const Threads& threads, size_t n, size_t slots, const Work& work,
                     const Finish& finish) {
  if (!threads.parallel() || slots <= 1) {
    for (size_t i = 0; i < n; ++i) {
      work(i, size_t(0));
      finish(i, size_t(0));
    }
    return;
  }
  // The pipeline hands items from stage to stage, and a serial stage from thread to thread,
  // inside oneTBB: these marks show ThreadSanitizer those hand-overs (TaskEdges), also when a
  // stage throws.
  TaskEdges edges;
  struct Marked {
    TaskEdges& edges;
    void* mark;
    Marked(TaskEdges& e, void* m) : edges(e), mark(m) {
      edges.begin();
      edges.enter(mark);
    }
    ~Marked() { edges.end(mark); }
  };
  struct Joined {  // the caller goes on after every item's stage, also when one threw
    TaskEdges& edges;
    ~Joined() { edges.join(); }
  } joined{edges};
  const std::unique_ptr<char[]> slotMarks = std::make_unique<char[]>(slots);
  char inputMark = 0, finishMark = 0;
  size_t next = 0;
  edges.spawn();
  threads.execute([&] {
    const auto input = [&](tbb::flow_control& control) {
      const Marked marked(edges, &inputMark);
      if (next == n) control.stop();
      return next < n ? next++ : n;
    };
    const auto parallel = [&](size_t i) {
      const Marked marked(edges, &slotMarks[i % slots]);
      work(i, i % slots);
      return i;
    };
    const auto inOrder = [&](size_t i) {
      const Marked serial(edges, &finishMark), marked(edges, &slotMarks[i % slots]);
      finish(i, i % slots);
    };
    tbb::parallel_pipeline(
        slots, tbb::make_filter<void, size_t>(tbb::filter_mode::serial_in_order, input) &
                   tbb::make_filter<size_t, size_t>(tbb::filter_mode::parallel, parallel) &
                   tbb::make_filter<size_t, void>(tbb::filter_mode::serial_in_order, inOrder));
  });
}

}  // namespace zrender
