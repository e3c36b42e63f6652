// sideBySide: every job runs, and the caller sees the error that running them in order would
// give, with one thread or several.

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>
#include <vector>

#include "zrender/base/SideBySide.hpp"
#include "zrender/base/Threads.hpp"

namespace zrender {
namespace {

// The message sideBySide throws when the jobs listed in `failing` throw their index, or "none".
std::string errorOf(const Threads* threads, size_t n, const std::vector<size_t>& failing) {
  try {
    sideBySide(threads, n, [&](size_t job) {
      for (size_t f : failing)
        if (f == job) throw std::runtime_error(std::to_string(job));
    });
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "none";
}

TEST(SideBySide, EveryJobRunsOnOneThreadOrSeveral) {
  const Threads one(1), two(2), three(3);
  for (const Threads* threads : {static_cast<const Threads*>(nullptr), &one, &two, &three}) {
    std::atomic<int> ran{0};
    sideBySide(threads, 5, [&](size_t job) { ran += 1 << (2 * job); });
    EXPECT_EQ(ran.load(), 1 + 4 + 16 + 64 + 256);
  }
}

TEST(SideBySide, TheFirstFailingJobsErrorWinsAsInOrder) {
  const Threads one(1), two(2), three(3);
  for (const Threads* threads : {static_cast<const Threads*>(nullptr), &one, &two, &three}) {
    EXPECT_EQ(errorOf(threads, 4, {0, 3}), "0");
    EXPECT_EQ(errorOf(threads, 4, {3, 1}), "1");
    EXPECT_EQ(errorOf(threads, 4, {3}), "3");
    EXPECT_EQ(errorOf(threads, 4, {}), "none");
  }
}

TEST(SideBySide, OneThreadStopsAtTheFirstError) {
  const Threads one(1);
  std::vector<size_t> ran;
  EXPECT_THROW(sideBySide(&one, 3,
                          [&](size_t job) {
                            ran.push_back(job);
                            if (job == 1) throw std::runtime_error("1");
                          }),
               std::runtime_error);
  EXPECT_EQ(ran, (std::vector<size_t>{0, 1}));
}

}  // namespace
}  // namespace zrender
