// The PNG of a frame is the same bytes at every thread count, also when several renders run
// at once on a loaded machine (docs/design.md, Image files): the encoder's strips are
// deflated by whichever thread is free, and nothing of that may show in the file.

#include <gtest/gtest.h>

#include <future>
#include <string>
#include <vector>

#include "support/CommandLineRuns.hpp"
#include "support/TestSupport.hpp"

namespace zrender {
namespace {

using test::readFile;
using test::runZrender;
using test::TempDir;

TEST(PngBytes, EveryThreadCountWritesTheSameBytesUnderLoad) {
  if (!test::referenceModel("bunny")) GTEST_SKIP() << "models/bunny is not linked";
  TempDir dir;
  const auto args = [&](int threads, int run) {
    return std::vector<std::string>{
        "crowd",
        "-a",
        "hierarchical",
        "--width",
        "600",
        "--height",
        "600",
        "--threads",
        std::to_string(threads),
        "-o",
        dir.file(std::to_string(threads) + "-" + std::to_string(run) + ".png")};
  };
  const test::RunResult first = runZrender(args(1, 0));
  ASSERT_EQ(first.status, 0) << first.err;
  const std::string expected = readFile(dir.file("1-0.png"));
  ASSERT_FALSE(expected.empty());
  // Four renders at once on two cores, 10 rounds: 40 files of 1, 2, 3 and 7 threads.
  const std::vector<int> counts = {1, 2, 3, 7};
  for (int round = 1; round <= 10; ++round) {
    std::vector<std::future<test::RunResult>> runs;
    for (int threads : counts)
      runs.push_back(std::async(std::launch::async,
                                [&, threads] { return runZrender(args(threads, round)); }));
    for (size_t i = 0; i < runs.size(); ++i) {
      const test::RunResult r = runs[i].get();
      const std::string name = std::to_string(counts[i]) + "-" + std::to_string(round) + ".png";
      ASSERT_EQ(r.status, 0) << name << ": " << r.err;
      EXPECT_TRUE(readFile(dir.file(name)) == expected) << name << " differs from 1-0.png";
    }
  }
}

}  // namespace
}  // namespace zrender
