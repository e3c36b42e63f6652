// sideBySide: both jobs run, and the caller sees the error that running them in order would
// give, with one thread or two.

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <string>

#include "zrender/base/SideBySide.hpp"
#include "zrender/base/Threads.hpp"

namespace zrender {
namespace {

// The message sideBySide throws for these jobs, or "none".
template <typename First, typename Second>
std::string errorOf(const Threads* threads, const First& first, const Second& second) {
  try {
    sideBySide(threads, first, second);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "none";
}

TEST(SideBySide, BothJobsRunOnOneThreadOrTwo) {
  const Threads one(1), two(2);
  for (const Threads* threads : {static_cast<const Threads*>(nullptr), &one, &two}) {
    std::atomic<int> ran{0};
    sideBySide(
        threads, [&] { ran += 1; }, [&] { ran += 10; });
    EXPECT_EQ(ran.load(), 11);
  }
}

TEST(SideBySide, TheFirstJobsErrorWinsAsInOrder) {
  const Threads one(1), two(2);
  const auto fails = [](const char* what) { return [what] { throw std::runtime_error(what); }; };
  const auto fine = [] {};
  for (const Threads* threads : {static_cast<const Threads*>(nullptr), &one, &two}) {
    EXPECT_EQ(errorOf(threads, fails("first"), fails("second")), "first");
    EXPECT_EQ(errorOf(threads, fails("first"), fine), "first");
    EXPECT_EQ(errorOf(threads, fine, fails("second")), "second");
    EXPECT_EQ(errorOf(threads, fine, fine), "none");
  }
}

TEST(SideBySide, OneThreadStopsAtTheFirstError) {
  const Threads one(1);
  bool secondRan = false;
  EXPECT_EQ(errorOf(
                &one, [] { throw std::runtime_error("first"); }, [&] { secondRan = true; }),
            "first");
  EXPECT_FALSE(secondRan);
}

}  // namespace
}  // namespace zrender
