// Hostile cameras and scenes end to end (docs/design.md, Camera and transforms, and Errors):
// impossible cameras and sizes are errors naming the key, in the settings file and on the
// command line; models behind the eye, through the eye plane and around the eye render the same
// picture with every algorithm.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "support/HostileRuns.hpp"
#include "zrender/visibility/VisibilityAlgorithm.hpp"

namespace zrender {
namespace {

namespace fs = std::filesystem;
using namespace test;

TEST(HostileCameras, ImpossibleCamerasNameTheKey) {
  TempDir dir;
  dir.write("m.obj", kSquareObj);
  const std::vector<std::pair<std::string, std::vector<std::string>>> cases = {
      {R"("eye": [0, 0, 2], "target": [0, 0, 2])", {"'s'", "key 'eye'", "target"}},
      {R"("eye": [0, 0, 2], "up": [0, 0, -3])", {"'s'", "key 'up'", "parallel"}},
      {R"("eye": [1, 1, 1], "up": [2, 2, 2])", {"'s'", "key 'up'", "parallel"}},
      {R"("fit": true, "up": [0, 0, 1])", {"'s'", "key 'up'", "parallel"}},  // no eye: down -z
      {R"("eye": [0, 0, 2], "project": [0, 1, 0.1, 10])", {"'s'", "key 'project'", "fovy"}},
      {R"("eye": [0, 0, 2], "project": [180, 1, 0.1, 10])", {"'s'", "key 'project'", "180"}},
      {R"("eye": [0, 0, 2], "project": [270, 1, 0.1, 10])", {"'s'", "key 'project'", "270"}},
      {R"("eye": [0, 0, 2], "project": [45, 1, 1, 1])", {"'s'", "key 'project'", "far"}},
      {R"("eye": [0, 0, 2], "project": [45, 1, -2, 2])", {"'s'", "key 'project'", "far"}},
      {R"("eye": [0, 0, 2], "project": [45, 1, 0, 2])", {"'s'", "key 'project'", "near"}},
      {R"("eye": [0, 0, 2], "msaa": 3)", {"'s'", "key 'msaa'"}},
      // Finite values whose projection overflows: 2 far near > 1e308, 1 / tan of a denormal
      // fovy, f / a denormal aspect.
      {R"("eye": [0, 0, 2], "project": [45, 1, 1, 1e308])", {"'s'", "key 'project'", "overflow"}},
      {R"("eye": [0, 0, 2], "project": [1e-320, 1, 1, 10])", {"'s'", "key 'project'", "overflow"}},
      {R"("eye": [0, 0, 2], "project": [45, 1e-310, 1, 10])", {"'s'", "key 'project'", "overflow"}},
  };
  for (const auto& [keys, mustName] : cases) {
    SCOPED_TRACE(keys);
    writeScene(dir, keys);
    expectQuickCleanError(renderScene(dir, "zbuffer"), mustName);
  }
  // The same on the command line, over a valid scene and over a model file.
  writeScene(dir, R"("eye": [0, 0, 2])");
  const std::vector<std::pair<std::vector<std::string>, std::string>> options = {
      {{"--eye", "0,0,2", "--target", "0,0,2"}, "key 'eye'"},
      {{"--up", "0,0,1"}, "key 'up'"},
      {{"--fov", "0"}, "key 'project'"},
      {{"--fov", "180"}, "key 'project'"},
      {{"--near", "5", "--far", "5"}, "key 'project'"},
      {{"--msaa", "3"}, "key 'msaa'"},
  };
  for (const auto& [extra, key] : options) {
    SCOPED_TRACE(extra[0]);
    expectQuickCleanError(renderScene(dir, "zbuffer", extra), {"'s'", key});
    expectQuickCleanError(renderModel(dir, "zbuffer", extra), {"m.obj", key});
  }
  EXPECT_FALSE(fs::exists(dir.file("out.png")));
}

TEST(HostileCameras, SizeOutOfRangeNamesTheKey) {
  TempDir dir;
  dir.write("m.obj", kSquareObj);
  for (const std::string key : {"width", "height"}) {
    for (const std::string value : {"0", "16385", "-1", "1e9"}) {
      SCOPED_TRACE(key + " " + value);
      dir.write("settings.json",
                R"({"s": {"path": "m.obj", "eye": [0, 0, 2], ")" + key + "\": " + value + "}}");
      expectQuickCleanError(renderScene(dir, "zbuffer"), {"settings.json", "'s'", "'" + key + "'"});
      writeScene(dir, R"("eye": [0, 0, 2])");
      const Outcome r = renderScene(dir, "zbuffer", {"--" + key, value});
      expectQuickCleanError(r, {key});
    }
  }
  // The limits themselves are fine: a 1 x 16384 strip.
  writeScene(dir, R"("eye": [0, 0, 2])");
  expectPicture(renderScene(dir, "zbuffer", {"--width", "1", "--height", "16384"}),
                dir.file("out.png"), 1, 16384);
  EXPECT_FALSE(fs::exists(dir.file("sq.png")));
}

TEST(HostileCameras, ModelEntirelyBehindTheCameraRendersTheBackground) {
  for (const std::string& algorithm : algorithmNames()) {
    SCOPED_TRACE(algorithm);
    TempDir dir;
    dir.write("m.obj", kSquareObj);
    // Looking along +z from z = 2: the square at z = 0 is behind the eye.
    writeScene(dir, R"("eye": [0, 0, 2], "target": [0, 0, 5], "background": [10, 20, 30])");
    for (const std::vector<std::string>& extra :
         {std::vector<std::string>{}, {"--no-cull"}, {"--msaa", "4"}}) {
      const cv::Mat image = expectPicture(renderScene(dir, algorithm, extra), dir.file("out.png"),
                                          kImageSize, kImageSize);
      ASSERT_FALSE(image.empty());
      EXPECT_EQ(cv::countNonZero(image.reshape(1) != 0), kImageSize * kImageSize * 3);  // no black
      EXPECT_EQ(image.at<cv::Vec3b>(0, 0), cv::Vec3b(30, 20, 10));
      EXPECT_EQ(image.at<cv::Vec3b>(kImageSize / 2, kImageSize / 2), cv::Vec3b(30, 20, 10));
    }
  }
}

// Renders the scene with every algorithm and expects the same, non-empty picture from each.
void expectAgreeingPictures(const TempDir& dir, const std::vector<std::string>& extra,
                            int minCovered) {
  cv::Mat reference;
  for (const std::string& algorithm : algorithmNames()) {
    SCOPED_TRACE(algorithm);
    const Outcome r = renderScene(dir, algorithm, extra);
    EXPECT_EQ(test::beyondSummary(r.err), "");
    const cv::Mat image = expectPicture(r, dir.file("out.png"), kImageSize, kImageSize);
    if (image.empty()) continue;
    EXPECT_GE(coveredPixels(image), minCovered);
    if (reference.empty()) reference = image;
    EXPECT_TRUE(sameImage(image, reference)) << algorithm << " differs from zbuffer";
  }
}

TEST(HostileCameras, TriangleThroughTheEyePlane) {
  TempDir dir;
  // From z = 5 behind the eye (z = 2) to z = -5 in front; the near plane cuts it.
  dir.write("m.obj",
            "v -1 -1 5\nv 1 -1 5\nv 0 1 -5\nf 1 2 3\nf 3 2 1\n"
            "v -3 0 5\nv 3 0 5\nv 0 0.5 -20\nf 4 5 6\n");
  writeScene(dir, R"("eye": [0, 0, 2], "project": [90, 0, 0.1, 10])");
  for (const auto& extra : {std::vector<std::string>{}, {"--no-cull"}, {"--msaa", "4"}}) {
    expectAgreeingPictures(dir, extra, 10);
  }
}

TEST(HostileCameras, EyeInsideTheModel) {
  TempDir dir;
  // A cube around the eye, faces outward: from inside every face is a back face.
  dir.write("m.obj",
            "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\n"
            "v -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
            "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n");
  writeScene(dir,
             R"("eye": [0.1, 0.2, 0.3], "target": [0.5, 0.1, -1], "project": [100, 0, 0.01, 10])");
  expectAgreeingPictures(dir, {"--no-cull"}, kImageSize * kImageSize);  // walls everywhere
  expectAgreeingPictures(dir, {"--no-cull", "--msaa", "4"}, kImageSize * kImageSize);
  for (const std::string& algorithm : algorithmNames()) {
    SCOPED_TRACE(algorithm);
    EXPECT_EQ(coveredPixels(expectPicture(renderScene(dir, algorithm), dir.file("out.png"),
                                          kImageSize, kImageSize)),
              0);  // culled
  }
}

}  // namespace
}  // namespace zrender
