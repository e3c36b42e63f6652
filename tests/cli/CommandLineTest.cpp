// The command line end to end (docs/design.md, Command line, and Timings and JSON): the built
// executable run in a temp folder; its outputs, JSON line, statistics, help and version.

#include <gtest/gtest.h>
#include <json/json.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
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
using test::matchesWithNumbers;
using test::parseJson;
using test::runZrender;
using test::settingsFor;
using test::TempDir;

TEST(CommandLine, RendersTheDefaultOutputName) {
  TempDir dir;
  dir.write("sq.obj", kSquareObj);
  dir.write("settings.json", settingsFor("sq.obj"));
  const auto r = runZrender({"sq"}, dir.path);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(test::beyondSummary(r.err), "");
  const cv::Mat image = test::imread(dir.file("sq.png"));
  ASSERT_FALSE(image.empty());
  EXPECT_EQ(image.cols, 32);
  // The square spans the middle half of the image: normal color (128, 128, 255) there.
  EXPECT_EQ(image.at<cv::Vec3b>(16, 16), cv::Vec3b(255, 128, 128));
  EXPECT_EQ(image.at<cv::Vec3b>(2, 2), cv::Vec3b(0, 0, 0));
  // Nothing else left behind (no temporary files).
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator()), 3);
}

TEST(CommandLine, ModelFileAsSceneUsesFit) {
  TempDir dir;
  const std::string model = dir.write("thing.obj", kSquareObj);
  const auto r = runZrender(
      {model, "-o", dir.file("out/thing.png"), "--width", "20", "--height", "10"}, dir.path);
  ASSERT_EQ(r.status, 0) << r.err;
  const cv::Mat image = test::imread(dir.file("out/thing.png"));  // parent folder created
  ASSERT_EQ(image.rows, 10);
  EXPECT_EQ(image.at<cv::Vec3b>(5, 10), cv::Vec3b(255, 128, 128));  // centred
}

TEST(CommandLine, JsonHasEveryDocumentedField) {
  TempDir dir;
  dir.write("sq.obj", kSquareObj);
  dir.write("settings.json", settingsFor("sq.obj"));
  const auto r = runZrender({"sq", "--json", "--repeat", "3", "-o", dir.file("a.png")}, dir.path);
  ASSERT_EQ(r.status, 0) << r.err;
  const Json::Value j = parseJson(r.out);
  ASSERT_TRUE(j.isObject());
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1);
  for (const char* key :
       {"scene", "algorithm", "width", "height", "msaa", "faces", "triangles", "load_ms",
        "prepare_ms", "transform_ms", "visibility_ms", "shade_ms", "raster_ms", "raster_ms_min",
        "frame_ms", "write_ms", "total_ms", "peak_rss_mb", "stats"})
    EXPECT_TRUE(j.isMember(key)) << key;
  for (const char* key : {"triangles_backface_culled", "triangles_clipped_away",
                          "triangles_rasterized", "triangles_hzb_culled", "octree_nodes_visited",
                          "octree_nodes_culled", "pixels_tested", "pixels_written"})
    EXPECT_TRUE(j["stats"].isMember(key)) << key;
  EXPECT_EQ(j["scene"].asString(), "sq");
  EXPECT_EQ(j["faces"].asInt(), 2);
  EXPECT_EQ(j["stats"]["triangles_rasterized"].asInt(), 2);
  // The square covers 16 x 16 pixels, each tested and written once.
  EXPECT_EQ(j["stats"]["pixels_written"].asInt(), 256);
  // With several frames each time is the median of its own values (README, Timings): the
  // median of the frames' sums need not equal the sum of the medians, so only the order of
  // each median and its minimum holds whatever the machine's load.
  EXPECT_LE(j["frame_ms_min"].asDouble(), j["frame_ms"].asDouble());
  EXPECT_LE(j["raster_ms_min"].asDouble(), j["raster_ms"].asDouble());
}

TEST(CommandLine, OneFrameHasFrameEqualToTransformPlusRaster) {
  TempDir dir;
  dir.write("sq.obj", kSquareObj);
  dir.write("settings.json", settingsFor("sq.obj"));
  const auto r = runZrender({"sq", "--json", "-o", dir.file("a.png")}, dir.path);
  ASSERT_EQ(r.status, 0) << r.err;
  const Json::Value j = parseJson(r.out);
  ASSERT_TRUE(j.isObject());
  // docs/design.md, Timings and JSON: frame_ms = transform_ms + raster_ms. The three are printed
  // rounded to 0.001 ms each, so the printed sum may be off by one unit of the last place.
  EXPECT_NEAR(j["frame_ms"].asDouble(), j["transform_ms"].asDouble() + j["raster_ms"].asDouble(),
              0.0011);
  // raster_ms = visibility_ms + shade_ms: the algorithm's work and the shading pass.
  EXPECT_NEAR(j["raster_ms"].asDouble(), j["visibility_ms"].asDouble() + j["shade_ms"].asDouble(),
              0.0011);
  EXPECT_EQ(j["frame_ms_min"].asDouble(), j["frame_ms"].asDouble());
  EXPECT_EQ(j["raster_ms_min"].asDouble(), j["raster_ms"].asDouble());
}

TEST(CommandLine, DepthAndIdOutputs) {
  TempDir dir;
  dir.write("sq.obj", kSquareObj);
  dir.write("settings.json", settingsFor("sq.obj"));
  const auto r = runZrender(
      {"sq", "-o", dir.file("c.png"), "--depth", dir.file("d.tif"), "--ids", dir.file("i.png")},
      dir.path);
  ASSERT_EQ(r.status, 0) << r.err;
  const cv::Mat depth = test::imread(dir.file("d.tif"), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(depth.type(), CV_32FC1);
  EXPECT_EQ(depth.at<float>(0, 0), 1.0f);
  EXPECT_GT(depth.at<float>(16, 16), 0.0f);
  EXPECT_LT(depth.at<float>(16, 16), 1.0f);
  const cv::Mat ids = test::imread(dir.file("i.png"), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(ids.type(), CV_8UC3);
  // The diagonal runs from bottom-left to top-right: the upper-left half is face 1 (f 1 3 4),
  // the lower-right half face 0; the image holds id + 1 in red.
  EXPECT_EQ(ids.at<cv::Vec3b>(10, 10), cv::Vec3b(0, 0, 2));
  EXPECT_EQ(ids.at<cv::Vec3b>(20, 20), cv::Vec3b(0, 0, 1));
  EXPECT_EQ(ids.at<cv::Vec3b>(1, 1), cv::Vec3b(0, 0, 0));

  const auto r16 =
      runZrender({"sq", "-o", dir.file("c.png"), "--depth", dir.file("d.png")}, dir.path);
  ASSERT_EQ(r16.status, 0) << r16.err;
  const cv::Mat depth16 = test::imread(dir.file("d.png"), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(depth16.type(), CV_16UC1);
  EXPECT_EQ(depth16.at<uint16_t>(0, 0), 65535);
  EXPECT_EQ(depth16.at<uint16_t>(16, 16), uint16_t(std::lround(depth.at<float>(16, 16) * 65535.0)));

  // Turned 40 degrees, the square's depth varies across it: every pixel of the 16-bit image is
  // the rounded float depth, round(depth x 65535), background 65535.
  const auto turned = runZrender(
      {"sq", "--angle", "40", "-o", dir.file("c.png"), "--depth", dir.file("t.tif")}, dir.path);
  ASSERT_EQ(turned.status, 0) << turned.err;
  ASSERT_EQ(
      runZrender({"sq", "--angle", "40", "-o", dir.file("c.png"), "--depth", dir.file("t.png")},
                 dir.path)
          .status,
      0);
  const cv::Mat t32 = test::imread(dir.file("t.tif"), cv::IMREAD_UNCHANGED);
  const cv::Mat t16 = test::imread(dir.file("t.png"), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(t32.type(), CV_32FC1);
  ASSERT_EQ(t16.type(), CV_16UC1);
  std::set<float> depths;
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 32; ++x) {
      const float d = t32.at<float>(y, x);
      EXPECT_EQ(t16.at<uint16_t>(y, x), uint16_t(std::lround(double(d) * 65535.0)))
          << x << ", " << y;
      depths.insert(d);
    }
  }
  EXPECT_GT(depths.size(), 10u);
}

// Two squares facing the eye on a 64 x 64 image (16 pixels per unit at z = 0). The front one
// at z = 0 (faces 0 and 1) covers pixels 16..47, exactly the pyramid's 16 x 16 tiles 1 and 2
// in x and y. The back one, the same size at z = -1 (faces 2 and 3), is 3 units from the eye,
// where the view spans [-3, 3], so it spans window x from 32 - 32 / 3 = 21.33 to 42.67: the
// pixel centres 21.5..42.5, 22 x 22 = 484 samples, every one behind the front square.
const char* kTwoSquares =
    "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
    "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\n"
    "f 1 2 3\nf 1 3 4\nf 5 6 7\nf 5 7 8\n";

TEST(CommandLine, StatsInWords) {
  TempDir dir;
  dir.write("two.obj", kTwoSquares);
  dir.write("settings.json", settingsFor("two.obj", "", "64"));
  // The z-buffer draws in face order: 1024 samples of the front square, then the 484 of the
  // back one, all tested and none written; 1024 / 1508 = 67.9045% of the tests win.
  // One thread: with more, the culling counters count per band of rows (docs/design.md,
  // Threads).
  const auto z = runZrender({"sq", "--stats", "--threads", "1", "-o", dir.file("z.png")}, dir.path);
  ASSERT_EQ(z.status, 0) << z.err;
  const std::string counters =
      "triangles: 4 rasterized, 0 back-facing, 0 clipped away, 0 degenerate, 0 rejected "
      "by the z-pyramid\n"
      "octree: 0 nodes visited, 0 rejected\n"
      "samples: 1508 depth tests, 1024 written (67.9045% won)\n";
  ASSERT_EQ(z.out.substr(0, counters.size()), counters);
  // Then the frame's times, which vary from run to run: only their form is fixed.
  EXPECT_TRUE(matchesWithNumbers(
      z.out.substr(counters.size()),
      "time: # ms transform, # ms visibility, # ms shading (raster # ms, frame # ms)\n"))
      << z.out;
  // The pyramid's tiles under the back square are all covered by the front one, so both of
  // its triangles are rejected before any sample test. With --json the words go to stderr.
  const auto h = runZrender({"sq", "--stats", "--json", "--threads", "1", "--alg", "hierarchical",
                             "-o", dir.file("h.png")},
                            dir.path);
  ASSERT_EQ(h.status, 0) << h.err;
  EXPECT_NE(h.err.find(" 2 rejected by the z-pyramid\n"), std::string::npos) << h.err;
  EXPECT_NE(h.err.find("samples: 1024 depth tests, 1024 written (100% won)\n"), std::string::npos)
      << h.err;
  EXPECT_EQ(std::count(h.out.begin(), h.out.end(), '\n'), 1);  // the JSON line alone
  // The interval scan-line adds its own counters, one per line.
  const auto i = runZrender(
      {"sq", "--stats", "--threads", "1", "--alg", "interval", "-o", dir.file("i.png")}, dir.path);
  ASSERT_EQ(i.status, 0) << i.err;
  EXPECT_NE(i.out.find("\nspans: "), std::string::npos) << i.out;
}

// MSAA 4 on a 4 x 4 image: depth and id images hold each pixel's nearest sample.
// Far square (faces 0, 1) at z = -2, 4 units from the eye where the view spans [-4, 4]: x from
// -4 to 1 puts its right edge at window x = (1 / 4 + 1) * 2 = 2.5, so pixel column 2 has two of
// its four samples (x = 2.25) on it and two (x = 2.75) on the background, and column 3 none.
// Near triangle (face 2) at z = 0, where window (x, y) = (X + 2, 2 - Y): its corners are at
// window (1.6, 1.6), (1.6, 2), (2, 1.6), so of all samples it covers only (1.75, 1.75), the
// last sample of pixel (1, 1).
TEST(CommandLine, MsaaDepthAndIdsHoldTheNearestSample) {
  TempDir dir;
  dir.write("m.obj",
            "v -4 -4 -2\nv 1 -4 -2\nv 1 4 -2\nv -4 4 -2\n"
            "v -0.4 0.4 0\nv -0.4 0 0\nv 0 0.4 0\n"
            "f 1 2 3\nf 1 3 4\nf 5 6 7\n");
  dir.write("settings.json", settingsFor("m.obj", R"(, "msaa": 4)", "4"));
  const auto r = runZrender(
      {"sq", "-o", dir.file("c.png"), "--depth", dir.file("d.tif"), "--ids", dir.file("i.png")},
      dir.path);
  ASSERT_EQ(r.status, 0) << r.err;
  const cv::Mat ids = test::imread(dir.file("i.png"), cv::IMREAD_UNCHANGED);
  const cv::Mat depth = test::imread(dir.file("d.tif"), cv::IMREAD_UNCHANGED);
  ASSERT_EQ(ids.type(), CV_8UC3);
  ASSERT_EQ(depth.type(), CV_32FC1);
  const auto id = [&](int x, int y) { return int(ids.at<cv::Vec3b>(y, x)[2]) - 1; };
  // One sample of four is enough, and the near face wins over the smaller ids of the far one.
  EXPECT_EQ(id(1, 1), 2);
  // Window depth (z_ndc + 1) / 2 with near 0.1, far 10: 95 / 99 at 2 units, 65 / 66 at 4.
  EXPECT_NEAR(depth.at<float>(1, 1), 95.0 / 99.0, 1e-6);
  EXPECT_NEAR(depth.at<float>(0, 0), 65.0 / 66.0, 1e-6);
  // Column 2: two far samples, two background: the far square. Its diagonal runs from window
  // (0, 4) to (2.5, 0), y = 4 - 1.6 x, so at x = 2.25 (y = 0.4) the sample at y = 0.25 is on
  // face 1 and the one at y = 0.75 on face 0; at equal depth the smaller id wins.
  EXPECT_EQ(id(2, 0), 0);
  EXPECT_NEAR(depth.at<float>(0, 2), 65.0 / 66.0, 1e-6);
  // Column 3: background (id image 0, depth 1).
  for (int y = 0; y < 4; ++y) {
    EXPECT_EQ(id(3, y), -1) << y;
    EXPECT_EQ(depth.at<float>(y, 3), 1.0f) << y;
  }
}

TEST(CommandLine, CullTurnsCullingBackOnForASceneWithout) {
  // The square seen from behind, in a scene that says "cull": false: drawn, unless --cull.
  TempDir dir;
  dir.write("sq.obj", kSquareObj);
  dir.write("settings.json", settingsFor("sq.obj", ", \"cull\": false"));
  const auto count = [&](const std::vector<std::string>& extra) {
    std::vector<std::string> args = {"sq", "-o", dir.file("back.png"), "--eye", "0,0,-2"};
    args.insert(args.end(), extra.begin(), extra.end());
    const auto r = runZrender(args, dir.path);
    EXPECT_EQ(r.status, 0) << r.err;
    cv::Mat gray;
    cv::cvtColor(test::imread(dir.file("back.png")), gray, cv::COLOR_BGR2GRAY);
    return cv::countNonZero(gray);
  };
  EXPECT_EQ(count({}), 256);
  EXPECT_EQ(count({"--cull"}), 0);
  expectCleanError(runZrender({"sq", "--cull", "--no-cull"}, dir.path), {"--cull", "--no-cull"});
}

TEST(CommandLine, UnknownSettingsKeyIsAWarning) {
  TempDir dir;
  dir.write("sq.obj", kSquareObj);
  dir.write("settings.json", settingsFor("sq.obj", R"(, "colour": 3)"));
  const auto r = runZrender({"sq", "-o", dir.file("a.png")}, dir.path);
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.err.find("zrender: warning: "), std::string::npos);
  EXPECT_NE(r.err.find("colour"), std::string::npos);
}

TEST(CommandLine, HelpExitsZero) {
  const auto r = runZrender({"--help"});
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("--alg"), std::string::npos);
}

TEST(CommandLine, VersionPrintsTheProjectVersionWithoutAScene) {
  TempDir dir;
  const auto r = runZrender({"--version"}, dir.path);
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.out, std::string("zrender ") + ZRENDER_VERSION + "\n");
  EXPECT_EQ(test::beyondSummary(r.err), "");
  EXPECT_TRUE(fs::is_empty(dir.path));
}

}  // namespace
}  // namespace zrender
