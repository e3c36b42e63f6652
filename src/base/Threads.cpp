#include "zrender/base/Threads.hpp"

#include <oneapi/tbb/info.h>

#include <algorithm>

namespace zrender {

Threads::Threads(int count) : count_(std::max(count, 1)) {
  if (count_ == 1) return;
  if (count_ > hardwareThreads())
    limit_ = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism,
                                                   size_t(count_));
  arena_ = std::make_unique<tbb::task_arena>(count_);
  slotMarks_ = std::make_unique<char[]>(size_t(count_));
}

int Threads::slot() const {
  if (!arena_) return 0;
  const int index = tbb::this_task_arena::current_thread_index();
  return index == tbb::task_arena::not_initialized ? 0 : index;
}

ThreadsStart::ThreadsStart(const Threads& threads) {
  if (threads.parallel()) thread_ = std::thread([&threads] { threads.start(); });
}

ThreadsStart::~ThreadsStart() {
  if (thread_.joinable()) thread_.join();
}

int hardwareThreads() {
  return std::max(tbb::info::default_concurrency(), 1);
}

}  // namespace zrender
