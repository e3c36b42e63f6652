// `zrender view` end to end on a virtual display (docs/design.md, The viewer): keys fed by
// --keys change what they say, the last frame saved equals what `zrender SCENE` renders for the
// command line the viewer prints, a contact sheet of the frames shown, the figures printed, and
// bad input (no display included) refused in one line before anything is written.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "support/CommandLineRuns.hpp"
#include "support/TestImages.hpp"
#include "support/TestSupport.hpp"
#include "support/VirtualDisplay.hpp"

namespace zrender {
namespace {

namespace fs = std::filesystem;
using test::expectCleanError;
using test::kSquareObj;
using test::matchesWithNumbers;
using test::readFile;
using test::runZrender;
using test::settingsFor;
using test::TempDir;
using test::VirtualDisplay;

// The arguments of the command line that follows `marker` in `out`, up to the end of its line,
// without the leading "zrender".
std::vector<std::string> commandAfter(const std::string& out, const std::string& marker) {
  const size_t at = out.find(marker);
  if (at == std::string::npos) {
    ADD_FAILURE() << "no '" << marker << "' in\n" << out;
    return {};
  }
  std::istringstream line(out.substr(at + marker.size(), out.find('\n', at) - at - marker.size()));
  std::vector<std::string> args;
  for (std::string word; line >> word;) args.push_back(word);
  EXPECT_EQ(args.at(0), "zrender");
  args.erase(args.begin());
  return args;
}

std::string valueOf(const std::vector<std::string>& args, const std::string& option) {
  for (size_t i = 0; i + 1 < args.size(); ++i)
    if (args[i] == option) return args[i + 1];
  ADD_FAILURE() << "no " << option;
  return "";
}

cv::Vec3d vectorOf(const std::vector<std::string>& args, const std::string& option) {
  cv::Vec3d v;
  std::istringstream in(valueOf(args, option));
  char comma = 0;
  in >> v[0] >> comma >> v[1] >> comma >> v[2];
  return v;
}

// A folder with the square scene `sq` (32 x 32, eye (0, 0, 2): its elevation is 0).
struct SquareFolder {
  SquareFolder() {
    dir.write("sq.obj", kSquareObj);
    dir.write("settings.json", settingsFor("sq.obj"));
  }
  TempDir dir;
};

TEST(ViewCommand, KeysChangeWhatTheySay) {
  VirtualDisplay display;
  ASSERT_FALSE(display.name().empty()) << display.error();
  SquareFolder sq;
  const auto r = runZrender({"view", "sq", "--keys", "space,space,w,w,s,m,t,q"}, sq.dir.path,
                            {60, 0}, display.environment());
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* said : {"key 'space': algorithm scanline\n", "key 'space': algorithm interval\n",
                           "key 'w': elevation 10 degrees\n", "key 'w': elevation 20 degrees\n",
                           "key 's': elevation 10 degrees\n", "key 'm': msaa 4\n",
                           "key 't': shading flat\n", "key 'q': quit\n",
                           "zrender view: 8 frames; the last one is zrender sq --alg interval "
                           "--shading flat --msaa 4 --cull --width 32 --height 32 "})
    EXPECT_NE(r.out.find(said), std::string::npos) << said << " in\n" << r.out;
  // The last frame's camera: 10 degrees above the target's horizontal plane, at distance 2.
  const auto args = commandAfter(r.out, "the last one is ");
  const cv::Vec3d offset = vectorOf(args, "--eye") - vectorOf(args, "--target");
  EXPECT_NEAR(cv::norm(offset), 2.0, 1e-12);
  EXPECT_NEAR(std::asin(offset[1] / 2.0) * 180.0 / CV_PI, 10.0, 1e-9);
  EXPECT_EQ(vectorOf(args, "--up"), cv::Vec3d(0, 1, 0));
}

TEST(ViewCommand, TheLastFrameSavedIsWhatTheRenderCommandWrites) {
  VirtualDisplay display;
  ASSERT_FALSE(display.name().empty()) << display.error();
  TempDir out;
  // The project's teapot, turned, tilted, nearer, phong-shaded, by the octree, with MSAA.
  const auto r = runZrender({"view", "teapot", "--width", "160", "--height", "120", "--keys",
                             "5,w,d,+,t,t,m", "--frames", "9", "--save-last", out.file("last.png")},
                            "", {60, 0}, display.environment());
  ASSERT_EQ(r.status, 0) << r.err;
  std::vector<std::string> args = commandAfter(r.out, "the last one is ");
  EXPECT_EQ(valueOf(args, "--alg"), "octree");
  EXPECT_EQ(valueOf(args, "--shading"), "phong");
  EXPECT_EQ(valueOf(args, "--msaa"), "4");
  args.insert(args.end(), {"-o", out.file("render.png")});
  const auto render = runZrender(args);
  ASSERT_EQ(render.status, 0) << render.err;
  const std::string saved = readFile(out.file("last.png"));
  EXPECT_FALSE(saved.empty());
  EXPECT_TRUE(saved == readFile(out.file("render.png"))) << "not byte for byte the same";
  const cv::Mat image = test::imread(out.file("last.png"));
  EXPECT_GT(cv::countNonZero(image.reshape(1)), 2000) << "no teapot";
}

TEST(ViewCommand, EnterSavesTheFrameBesideTheSceneAndSaysHowToRenderIt) {
  VirtualDisplay display;
  ASSERT_FALSE(display.name().empty()) << display.error();
  SquareFolder sq;
  const auto r = runZrender({"view", "sq", "--keys", "a,enter,enter,q"}, sq.dir.path, {60, 0},
                            display.environment());
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("zrender view: saved sq-view-001.png, the image of: zrender sq "),
            std::string::npos)
      << r.out;
  EXPECT_TRUE(fs::exists(sq.dir.file("sq-view-002.png")));
  std::vector<std::string> args = commandAfter(r.out, "saved sq-view-001.png, the image of: ");
  args.insert(args.end(), {"-o", "render.png"});
  ASSERT_EQ(runZrender(args, sq.dir.path).status, 0);
  EXPECT_TRUE(readFile(sq.dir.file("sq-view-001.png")) == readFile(sq.dir.file("render.png")));
}

TEST(ViewCommand, AContactSheetOfTheFramesShownAndTheFiguresPrinted) {
  VirtualDisplay display;
  ASSERT_FALSE(display.name().empty()) << display.error();
  SquareFolder sq;
  const auto r = runZrender({"view", "sq", "--keys", "2,3,m,enter", "--frames", "5",
                             "--contact-sheet", sq.dir.file("sheet.png")},
                            sq.dir.path, {60, 0}, display.environment());
  ASSERT_EQ(r.status, 0) << r.err;
  // The frames on screen at the three keys that changed something, and the last: 2 x 2 tiles
  // of 32 x 32 (a fifth would make it 3 x 2).
  const cv::Mat sheet = test::imread(sq.dir.file("sheet.png"));
  EXPECT_EQ(sheet.cols, 64);
  EXPECT_EQ(sheet.rows, 64);
  // The last tile is the last frame, overlay included: not black below it.
  EXPECT_GT(cv::countNonZero(sheet(cv::Rect(32, 48, 32, 16)).clone().reshape(1)), 0);
  // The figures, as the overlay shows them, once more at the end: times of the two frames
  // since MSAA changed.
  const size_t at = r.out.rfind("zrender view: interval");
  ASSERT_NE(at, std::string::npos) << r.out;
  const std::string last = r.out.substr(at);
  const std::string figures =
      "zrender view: interval  normal  msaa 4  cull on | frame # ms (median of 2)  # fps | "
      "culled: 0 back-facing, 0 clipped, 0 by the z-pyramid | drawn: 2 triangles; octree "
      "nodes: 0 of 0 culled\n";
  EXPECT_TRUE(matchesWithNumbers(last.substr(0, last.find('\n') + 1), figures)) << r.out;
}

TEST(ViewCommand, BadInputIsOneLineAndWritesNothing) {
  VirtualDisplay display;
  ASSERT_FALSE(display.name().empty()) << display.error();
  SquareFolder sq;
  const std::vector<std::string> saving = {"--save-last", sq.dir.file("out/last.png"),
                                           "--contact-sheet", sq.dir.file("out/sheet.png")};
  // Each run stops after a frame, should its bad input be taken.
  const auto run = [&](std::vector<std::string> args, const test::Environment& environment) {
    args.insert(args.begin(), {"view", "sq"});
    args.insert(args.end(), saving.begin(), saving.end());
    if (std::find(args.begin(), args.end(), "--frames") == args.end())
      args.insert(args.end(), {"--frames", "1"});
    return runZrender(args, sq.dir.path, {60, 0}, environment);
  };
  const test::Environment onDisplay = display.environment();
  expectCleanError(run({"--keys", "space,jump"}, onDisplay), {"--keys", "'jump'"});
  expectCleanError(run({"--frames", "0"}, onDisplay), {"--frames", "0"});
  expectCleanError(run({"--key-interval", "0"}, onDisplay), {"--key-interval"});
  expectCleanError(runZrender({"view", "sq", "--frames", "1", "--save-last", "last.gif"},
                              sq.dir.path, {60, 0}, onDisplay),
                   {"--save-last", "last.gif", ".png"});
  expectCleanError(runZrender({"view", "sq", "--frames", "1", "--contact-sheet", "sheet.jpg"},
                              sq.dir.path, {60, 0}, onDisplay),
                   {"--contact-sheet", "sheet.jpg"});
  expectCleanError(run({}, {{"DISPLAY", std::nullopt}}), {"view: no display", "DISPLAY"});
  expectCleanError(run({}, {{"DISPLAY", ":65000"}}), {"view: no display", "':65000'"});
  expectCleanError(run({"--alg", "fast"}, onDisplay), {"--alg", "'fast'"});
  EXPECT_FALSE(fs::exists(sq.dir.file("out/last.png")));
  EXPECT_FALSE(fs::exists(sq.dir.file("out/sheet.png")));
  EXPECT_FALSE(fs::exists(sq.dir.file("last.gif")));
  EXPECT_FALSE(fs::exists(sq.dir.file("sheet.jpg")));
}

}  // namespace
}  // namespace zrender
