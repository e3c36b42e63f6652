// --threads end to end (docs/design.md, Command line): a render reports its thread count and
// writes the image one thread writes; bench with more than one thread adds the speed-up over
// one thread and checks the buffers against one thread's.

#include <gtest/gtest.h>
#include <json/json.h>

#include <fstream>
#include <sstream>
#include <string>

#include "support/CommandLineRuns.hpp"
#include "support/TestSupport.hpp"

namespace zrender {
namespace {

using test::kSquareObj;
using test::runZrender;
using test::settingsFor;
using test::TempDir;

Json::Value parseLine(const std::string& text) {
  Json::Value v;
  std::istringstream in(text);
  in >> v;
  return v;
}

TEST(ThreadsOption, RenderReportsThreadsAndWritesTheOneThreadImage) {
  TempDir dir;
  dir.write("sq.obj", kSquareObj);
  dir.write("settings.json", settingsFor("sq.obj", "", "96"));
  const auto one =
      runZrender({"sq", "--threads", "1", "--json", "-o", dir.file("1.png")}, dir.path);
  const auto three =
      runZrender({"sq", "--threads", "3", "--json", "-o", dir.file("3.png")}, dir.path);
  ASSERT_EQ(one.status, 0) << one.err;
  ASSERT_EQ(three.status, 0) << three.err;
  EXPECT_EQ(parseLine(one.out)["threads"].asInt(), 1);
  EXPECT_EQ(parseLine(three.out)["threads"].asInt(), 3);
  EXPECT_EQ(test::readFile(dir.file("1.png")), test::readFile(dir.file("3.png")));
  EXPECT_EQ(test::beyondSummary(three.err),
            "");  // oneTBB says nothing about more threads than cores
}

// With several threads the buffers are made while the model loads (FrameMemory): the files
// of one thread still, MSAA, depth and ids included.
TEST(ThreadsOption, BuffersMadeWhileLoadingGiveTheOneThreadFiles) {
  TempDir dir;
  dir.write("sq.obj", kSquareObj);
  dir.write("settings.json", settingsFor("sq.obj", R"(, "msaa": 4)", "48"));
  for (const char* threads : {"1", "2"}) {
    const std::string t(threads);
    const auto r = runZrender({"sq", "--threads", t, "-o", dir.file(t + ".png"), "--depth",
                               dir.file(t + ".tiff"), "--ids", dir.file(t + "-ids.png")},
                              dir.path);
    ASSERT_EQ(r.status, 0) << r.err;
  }
  for (const char* name : {".png", ".tiff", "-ids.png"})
    EXPECT_EQ(test::readFile(dir.file(std::string("1") + name)),
              test::readFile(dir.file(std::string("2") + name)))
        << name;
}

TEST(ThreadsOption, BenchWithThreadsAddsTheSpeedUpOverOneThread) {
  TempDir dir;
  dir.write("sq.obj", kSquareObj);
  dir.write("settings.json", settingsFor("sq.obj", R"(, "bench": true)"));
  const auto r = runZrender(
      {"bench", "--threads", "2", "--repeat", "2", "--json", dir.file("b.json")}, dir.path);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("2 threads"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("speed-up over one thread"), std::string::npos) << r.out;
  std::ifstream json(dir.file("b.json"));
  Json::Value results;
  json >> results;
  EXPECT_EQ(results["threads"].asInt(), 2);
  const Json::Value& rows = results["cells"];
  ASSERT_GT(rows.size(), 0u);
  for (const Json::Value& row : rows) {
    EXPECT_EQ(row["one_thread_frame_ms"]["samples"].size(), 2u) << row;
    EXPECT_TRUE(row["identical"].asBool()) << row;
  }
  // One thread, the default: no speed-up column.
  const auto plain = runZrender({"bench", "--repeat", "1"}, dir.path);
  ASSERT_EQ(plain.status, 0) << plain.err;
  EXPECT_EQ(plain.out.find("speed-up over one thread"), std::string::npos) << plain.out;
  EXPECT_NE(plain.out.find("one thread"), std::string::npos) << plain.out;
}

}  // namespace
}  // namespace zrender
