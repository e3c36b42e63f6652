// Threads::forEachInOrder: every task once, started in the order given.

#include <gtest/gtest.h>

#include <atomic>
#include <vector>

#include "zrender/base/Threads.hpp"

namespace zrender {
namespace {

TEST(Threads, ForEachInOrderRunsEveryTaskOnce) {
  const std::vector<uint32_t> order{3, 0, 5, 1, 4, 2};
  for (int count : {1, 2, 3, 7}) {
    const Threads threads(count);
    std::vector<std::atomic<int>> runs(order.size());
    threads.forEachInOrder(order, [&](size_t task) { ++runs[task]; });
    for (size_t t = 0; t < runs.size(); ++t)
      EXPECT_EQ(runs[t].load(), 1) << "task " << t << ", " << count << " threads";
  }
}

TEST(Threads, ForEachInOrderOnOneThreadRunsTheOrderGiven) {
  // With several threads a task may start before the one given before it (its thread took it
  // later but ran sooner): only one thread gives an order to expect.
  const std::vector<uint32_t> order{3, 0, 5, 1, 4, 2};
  std::vector<size_t> started;
  Threads(1).forEachInOrder(order, [&](size_t task) { started.push_back(task); });
  EXPECT_EQ(started, std::vector<size_t>(order.begin(), order.end()));
}

}  // namespace
}  // namespace zrender
