// The turntable (--turntable, docs/design.md, Command line): every frame written by its pattern
// or into a video, a contact sheet, and patterns and frames that cannot be written refused
// before the first frame.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <iterator>
#include <string>

#include <opencv2/imgproc.hpp>

#include "support/CommandLineRuns.hpp"
#include "support/TestImages.hpp"
#include "support/TestSupport.hpp"

namespace zrender {
namespace {

namespace fs = std::filesystem;
using test::expectCleanError;
using test::kSquareObj;
using test::runZrender;
using test::settingsFor;
using test::TempDir;

TEST(Turntable, WritesEveryFrameAndAContactSheet) {
  TempDir dir;
  dir.write("sq.obj", kSquareObj);
  dir.write("settings.json", settingsFor("sq.obj"));
  const auto r = runZrender({"sq", "--turntable", "4", "-o", dir.file("f/%02d.png"), "--no-cull",
                             "--contact-sheet", dir.file("sheet.png"), "--json"},
                            dir.path);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 4);  // a JSON line per frame
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(fs::exists(dir.file("f/0" + std::to_string(i) + ".png")));
  // Frame 1 is a quarter turn about the vertical axis: the square is seen edge-on, so
  // (almost) nothing is drawn, while frame 0 shows it whole; frame 2 shows its back.
  const cv::Mat f0 = test::imread(dir.file("f/00.png")), f1 = test::imread(dir.file("f/01.png"));
  cv::Mat gray0, gray1;
  cv::cvtColor(f0, gray0, cv::COLOR_BGR2GRAY);
  cv::cvtColor(f1, gray1, cv::COLOR_BGR2GRAY);
  EXPECT_EQ(cv::countNonZero(gray0), 256);
  EXPECT_LT(cv::countNonZero(gray1), 40);
  const cv::Mat sheet = test::imread(dir.file("sheet.png"));
  EXPECT_EQ(sheet.cols, 64);  // 2 x 2 tiles of 32 x 32
  EXPECT_EQ(sheet.rows, 64);
}

TEST(Turntable, WritesAVideo) {
  TempDir dir;
  dir.write("sq.obj", kSquareObj);
  dir.write("settings.json", settingsFor("sq.obj"));
  const auto r = runZrender({"sq", "--turntable", "6", "-o", dir.file("spin.avi")}, dir.path);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(test::videoFrameCount(dir.file("spin.avi")), 6);
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator()), 3);
}

TEST(Turntable, PatternWithoutADirectiveIsRefused) {
  TempDir dir;
  dir.write("sq.obj", kSquareObj);
  dir.write("settings.json", settingsFor("sq.obj"));
  expectCleanError(runZrender({"sq", "--turntable", "3", "-o", dir.file("x.png")}, dir.path),
                   {"{view}", "x.png"});
}

TEST(Turntable, PercentSignsAndAWidthInThePattern) {
  TempDir dir;
  dir.write("sq.obj", kSquareObj);
  dir.write("settings.json", settingsFor("sq.obj"));
  const auto r =
      runZrender({"sq", "--turntable", "2", "-o", dir.file("f/100%%-%03d.png")}, dir.path);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(fs::exists(dir.file("f/100%-000.png")));
  EXPECT_TRUE(fs::exists(dir.file("f/100%-001.png")));
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.file("f")), fs::directory_iterator()), 2);
}

TEST(Turntable, AFrameThatCannotBeWrittenFailsBeforeTheFirstFrame) {
  // A folder named like frame 2: the run fails before frames 0 and 1 are written.
  TempDir dir;
  dir.write("sq.obj", kSquareObj);
  dir.write("settings.json", settingsFor("sq.obj"));
  fs::create_directories(dir.file("f/f2.png"));
  expectCleanError(runZrender({"sq", "--turntable", "4", "-o", dir.file("f/f%d.png")}, dir.path),
                   {dir.file("f/f2.png"), "a folder has that name"});
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.file("f")), fs::directory_iterator()), 1);
}

}  // namespace
}  // namespace zrender
