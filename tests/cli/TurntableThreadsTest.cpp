// A turntable on several threads renders its frames at once (docs/design.md, Threads): the same
// frame files, contact sheet, video and JSON lines as on one thread, in frame order; a frame
// that cannot be written stops the run with its error and leaves only whole files.

#include <gtest/gtest.h>
#include <json/json.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "support/CommandLineRuns.hpp"
#include "support/HostileRuns.hpp"
#include "support/TestSupport.hpp"

namespace zrender {
namespace {

namespace fs = std::filesystem;
using test::readFile;
using test::runZrender;
using test::TempDir;

// More frames than threads, and not a multiple of 2 or 3: every renderer draws several frames.
constexpr int kFrames = 7;

std::vector<Json::Value> jsonLines(const std::string& text) {
  std::vector<Json::Value> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    Json::Value v;
    std::istringstream(line) >> v;
    lines.push_back(v);
  }
  return lines;
}

// The project's `shapes` scene (a model of the repository, settings.json's entry), small.
std::vector<std::string> shapesTurntable(const std::string& algorithm, int threads,
                                         const std::string& folder) {
  return {"shapes",
          "--width",
          "64",
          "--height",
          "48",
          "--alg",
          algorithm,
          "--turntable",
          std::to_string(kFrames),
          "--repeat",
          "2",
          "--threads",
          std::to_string(threads),
          "-o",
          folder + "/%d.png",
          "--contact-sheet",
          folder + "/sheet.png",
          "--json"};
}

TEST(TurntableThreads, FramesSheetAndJsonLinesAreOneThreadsOnEveryAlgorithm) {
  TempDir dir;
  for (const char* algorithm : {"zbuffer", "scanline", "interval", "hierarchical", "octree"}) {
    SCOPED_TRACE(algorithm);
    const auto one = runZrender(shapesTurntable(algorithm, 1, dir.file("1")));
    ASSERT_EQ(one.status, 0) << one.err;
    const std::vector<Json::Value> oneLines = jsonLines(one.out);
    ASSERT_EQ(oneLines.size(), size_t(kFrames)) << one.out;
    for (int threads : {2, 3}) {
      SCOPED_TRACE(std::to_string(threads) + " threads");
      const std::string folder = dir.file(std::to_string(threads));
      const auto r = runZrender(shapesTurntable(algorithm, threads, folder));
      ASSERT_EQ(r.status, 0) << r.err;
      for (int frame = 0; frame < kFrames; ++frame) {
        const std::string name = "/" + std::to_string(frame) + ".png";
        EXPECT_EQ(readFile(folder + name), readFile(dir.file("1") + name)) << name;
      }
      EXPECT_EQ(readFile(folder + "/sheet.png"), readFile(dir.file("1/sheet.png")));
      EXPECT_EQ(std::distance(fs::directory_iterator(folder), fs::directory_iterator()),
                kFrames + 1);  // no temporary file left

      // A line per frame in frame order, with one thread's fields; its counters are one
      // thread's too (each frame is drawn by a renderer of one thread), so each line is its
      // own frame's.
      const std::vector<Json::Value> lines = jsonLines(r.out);
      ASSERT_EQ(lines.size(), size_t(kFrames)) << r.out;
      for (int frame = 0; frame < kFrames; ++frame) {
        const Json::Value& line = lines[size_t(frame)];
        const Json::Value& oneLine = oneLines[size_t(frame)];
        EXPECT_EQ(line["frame"].asInt(), frame);
        EXPECT_EQ(line["threads"].asInt(), threads);
        EXPECT_EQ(line.getMemberNames(), oneLine.getMemberNames());
        EXPECT_EQ(line["stats"], oneLine["stats"]) << "frame " << frame;
        for (const char* key : {"algorithm", "scene", "width", "height", "faces", "repeat"})
          EXPECT_EQ(line[key], oneLine[key]) << key;
        EXPECT_GE(line["total_ms"].asDouble(),
                  frame > 0 ? lines[frame - 1]["total_ms"].asDouble() : 0.0);
      }
    }
    fs::remove_all(dir.file("1"));
    fs::remove_all(dir.file("2"));
    fs::remove_all(dir.file("3"));
  }
}

TEST(TurntableThreads, VideoIsOneThreads) {
  TempDir dir;
  std::vector<std::string> files;
  for (int threads : {1, 2, 3}) {
    const std::string file = dir.file(std::to_string(threads) + ".avi");
    const auto r =
        runZrender({"shapes", "--width", "64", "--height", "48", "--turntable",
                    std::to_string(kFrames), "--threads", std::to_string(threads), "-o", file});
    ASSERT_EQ(r.status, 0) << r.err;
    files.push_back(readFile(file));
  }
  EXPECT_FALSE(files[0].empty());
  EXPECT_EQ(files[1], files[0]);
  EXPECT_EQ(files[2], files[0]);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator()), 3);
}

TEST(TurntableThreads, FewerFramesThanThreadsAreSplitAndOneThreads) {
  // 2 frames on 3 threads: each frame split over the threads (frames at once would leave one
  // idle), the files still one thread's.
  TempDir dir;
  for (int threads : {1, 3}) {
    const auto r =
        runZrender({"shapes", "--width", "64", "--height", "48", "--turntable", "2", "--threads",
                    std::to_string(threads), "-o", dir.file(std::to_string(threads) + "/%d.png")});
    ASSERT_EQ(r.status, 0) << r.err;
  }
  for (const char* name : {"/0.png", "/1.png"})
    EXPECT_EQ(readFile(dir.file("3") + name), readFile(dir.file("1") + name)) << name;
}

TEST(TurntableThreads, AFrameThatFailsPartWayLeavesOnlyWholeFiles) {
  // A grid of random colors seen edge-on in frame 0 (and 4) makes a PNG of about 2.1 KB; the
  // frames between see its face, 7 KB and more. Under a 4 KB file size limit, writing frame 1
  // stops part way with EFBIG while frame 0 (and, on several threads, others) is written.
  TempDir dir;
  dir.write("m.obj", test::gridModel(40, 40));
  const auto args = [&](int threads, const std::string& folder) {
    return std::vector<std::string>{"m.obj",
                                    "--turntable",
                                    "8",
                                    "--angle",
                                    "90",
                                    "--axis",
                                    "0,1,0",
                                    "--no-cull",
                                    "--shading",
                                    "random",
                                    "--width",
                                    "96",
                                    "--height",
                                    "96",
                                    "--threads",
                                    std::to_string(threads),
                                    "-o",
                                    folder + "/%d.png",
                                    "--contact-sheet",
                                    folder + "/sheet.png"};
  };
  const auto whole = runZrender(args(1, "whole"), dir.path);
  ASSERT_EQ(whole.status, 0) << whole.err;
  ASSERT_LT(readFile(dir.file("whole/0.png")).size(), 4096u);
  ASSERT_GT(readFile(dir.file("whole/1.png")).size(), 4096u);

  for (int threads : {1, 2, 3}) {
    SCOPED_TRACE(std::to_string(threads) + " threads");
    const std::string folder = "cut" + std::to_string(threads);
    const test::Outcome r = test::runLimited(args(threads, folder), dir.path, 60, 4096);
    test::expectQuickCleanError(r, {folder + "/", ".png", "cannot write file"});
    // What is there is whole frames, each the frame of the run without a limit; no sheet and
    // no temporary file.
    for (const auto& entry : fs::directory_iterator(dir.file(folder))) {
      const std::string name = entry.path().filename().string();
      EXPECT_NE(name, "sheet.png");
      EXPECT_NE(name[0], '.') << name;
      EXPECT_EQ(readFile(entry.path().string()), readFile(dir.file("whole/" + name))) << name;
    }
    EXPECT_FALSE(fs::exists(dir.file(folder + "/1.png")));
  }
}

}  // namespace
}  // namespace zrender
