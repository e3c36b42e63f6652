// The scene of a render resolved from a settings file or a model file and the options
// (resolveScene, defaultSceneForModel), and the camera rule of a model file named on the
// command line: fit frames the model around the camera options the user typed, and leaves those
// as given. Checked for every combination of given and missing --eye, --target, --near and
// --far, against a pinhole projection written out here (not zrender's lookAt and perspective)
// and fit's distances worked out by hand.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "support/SettingsParsing.hpp"
#include "support/TestImages.hpp"
#include "support/TestSupport.hpp"
#include "zrender/cli/SceneResolution.hpp"

namespace zrender {
namespace {

namespace fs = std::filesystem;
using test::TempDir;
using test::validateError;

constexpr int kWidth = 64, kHeight = 48;
constexpr double kFovy = 30.0;  // degrees; the vertical half-angle (15) is the smaller one
const Vec3 kGivenEye(0.3, 0.2, 5.0), kGivenTarget(0.0, 0.0, 0.0), kUp(0.0, 1.0, 0.0);
constexpr double kGivenNear = 1.0, kGivenFar = 10.0;

// A 2 x 2 square facing +Z, turned by `angle` degrees about +Y (the model rotation).
struct Square {
  std::vector<Vec3> corners;  // model space, counter-clockwise seen from +Z
  double angle;
  Vec3 centre;  // world space: the centre of its bounding sphere, of radius sqrt(2)
};

// The square at the origin, and one off-centre (centred at (2, 1, 0) in the model) and turned
// by 30 degrees: its centre goes to (2 cos 30, 1, -2 sin 30).
std::vector<Square> squares() {
  return {Square{{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}, 0.0, Vec3(0, 0, 0)},
          Square{{{1, 0, 0}, {3, 0, 0}, {3, 2, 0}, {1, 2, 0}},
                 30.0,
                 Vec3(2.0 * std::cos(CV_PI / 6.0), 1.0, -2.0 * std::sin(CV_PI / 6.0))}};
}

Vec3 turned(const Vec3& p, double degrees) {  // about +Y, right-hand rule
  const double c = std::cos(degrees * CV_PI / 180.0), s = std::sin(degrees * CV_PI / 180.0);
  return Vec3(c * p[0] + s * p[2], p[1], -s * p[0] + c * p[2]);
}

// gluLookAt + gluPerspective + the viewport, written out: pixel position (x right, y down).
cv::Point2d project(const Vec3& eye, const Vec3& target, const Vec3& p) {
  const Vec3 f = cv::normalize(target - eye), s = cv::normalize(f.cross(kUp)), u = s.cross(f);
  const Vec3 e = p - eye;
  const double depth = e.dot(f), t = std::tan(kFovy * CV_PI / 360.0);
  const double xNdc = e.dot(s) / (depth * t * kWidth / kHeight), yNdc = e.dot(u) / (depth * t);
  return {(xNdc + 1.0) * kWidth / 2.0, (1.0 - yNdc) * kHeight / 2.0};
}

struct Given {
  bool eye, target, near, far;
};

std::string describe(const Given& g) {
  std::string s;
  if (g.eye) s += " --eye";
  if (g.target) s += " --target";
  if (g.near) s += " --near";
  if (g.far) s += " --far";
  return s.empty() ? " (no camera option)" : s;
}

TEST(SceneResolution, AModelFileKeepsEveryCameraOptionGivenAndFitsTheRest) {
  TempDir dir;
  const std::string settings = dir.write("settings.json", "{}");
  const std::string model = dir.write("sq.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const double r = 1.05 * std::sqrt(2.0);                // the sphere with fit's margin
  const double d = r / std::sin(kFovy * CV_PI / 360.0);  // fit's distance from its centre
  for (const Square& square : squares()) {
    std::vector<std::vector<int>> face{{0, 1, 2, 3}};
    const auto mesh = test::makeMesh(square.corners, face);
    for (int bits = 0; bits < 16; ++bits) {
      const Given given{(bits & 1) != 0, (bits & 2) != 0, (bits & 4) != 0, (bits & 8) != 0};
      const std::string label = "angle " + std::to_string(square.angle) + describe(given);
      SceneOverrides o;
      o.width = kWidth, o.height = kHeight, o.fov = kFovy, o.up = kUp, o.angle = square.angle;
      o.shading = "id";
      if (given.eye) o.eye = kGivenEye;
      if (given.target) o.target = kGivenTarget;
      if (given.near) o.near = kGivenNear;
      if (given.far) o.far = kGivenFar;
      Warnings warnings;
      const SceneSettings s =
          resolveScene(model, std::optional<std::filesystem::path>(settings), o, warnings);
      Warnings sceneWarnings;
      const Scene scene = makeScene(s, mesh);
      const Camera cam = makeCamera(scene);

      // The rule: a missing target is the model's centre; a missing eye lies on +Z from the
      // target at fit's distance; a missing near or far hugs the sphere from the eye.
      const Vec3 target = given.target ? kGivenTarget : square.centre;
      const Vec3 eye = given.eye ? kGivenEye : target + Vec3(0, 0, d);
      const double centreDepth = (square.centre - eye).dot(cv::normalize(target - eye));
      for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(cam.eye[a], eye[a], 1e-9) << label;
        EXPECT_NEAR(cam.target[a], target[a], 1e-9) << label;
      }
      EXPECT_NEAR(cam.near, given.near ? kGivenNear : centreDepth - r, 1e-9) << label;
      EXPECT_NEAR(cam.far, given.far ? kGivenFar : centreDepth + r, 1e-9) << label;

      // The picture: exactly the pixels whose centres the projected square holds (centres
      // within 1/100 pixel of an edge are left out: snapping may go either way there).
      const test::Rendered image = test::render(scene, "zbuffer");
      std::vector<cv::Point2d> quad;
      for (const Vec3& c : square.corners)
        quad.push_back(project(eye, target, turned(c, square.angle)));
      int covered = 0, mismatched = 0;
      for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
          const cv::Point2d p(x + 0.5, y + 0.5);
          double nearestEdge = HUGE_VAL;
          int left = 0, right = 0;
          for (size_t i = 0; i < quad.size(); ++i) {
            const cv::Point2d a = quad[i], b = quad[(i + 1) % quad.size()];
            const double side = ((b - a).x * (p - a).y - (b - a).y * (p - a).x) / cv::norm(b - a);
            nearestEdge = std::min(nearestEdge, std::abs(side));
            left += side<0.0, right += side> 0.0;
          }
          const bool inside = left == 4 || right == 4;
          if (nearestEdge < 0.01) continue;
          const bool drawn = image.buffer.row(y)[x] != kClearKey;
          covered += inside;
          mismatched += inside != drawn;
        }
      }
      EXPECT_EQ(mismatched, 0) << label;
      EXPECT_GT(covered, 200) << label;  // the square is in view, not clipped away
    }
  }
}

TEST(SceneResolution, ASquareIsAsTallAsWithTheSameCameraInASettingsFile) {
  // The square at the origin, seen from (0.3, 0.2, 5) with fovy 30: 2 / (2 * 5 tan 15) of the
  // 48 rows is 35.8 rows; given on the command line, the camera is the settings file's.
  TempDir dir;
  dir.write("sq.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n");
  dir.write("settings.json", R"({"sq": {"path": "sq.obj", "width": 64, "height": 48,
    "eye": [0.3, 0.2, 5], "target": [0, 0, 0], "up": [0, 1, 0], "project": [30, 0, 1, 10],
    "shading": "id"}})");
  const auto fromSettings = test::runZrender({"sq", "-o", dir.file("a.png")}, dir.path);
  ASSERT_EQ(fromSettings.status, 0) << fromSettings.err;
  const auto fromOptions = test::runZrender(
      {"sq.obj", "--shading", "id",       "--width", "64",   "--height", "48",
       "--eye",  "0.3,0.2,5", "--target", "0,0,0",   "--up", "0,1,0",    "--fov",
       "30",     "--near",    "1",        "--far",   "10",   "-o",       dir.file("b.png")},
      dir.path);
  ASSERT_EQ(fromOptions.status, 0) << fromOptions.err;
  EXPECT_EQ(test::beyondSummary(fromOptions.err), "");
  const cv::Mat a = test::imread(dir.file("a.png")), b = test::imread(dir.file("b.png"));
  ASSERT_FALSE(a.empty());
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);
  int top = kHeight, bottom = -1;
  for (int y = 0; y < a.rows; ++y)
    for (int x = 0; x < a.cols; ++x)
      if (a.at<cv::Vec3b>(y, x) != cv::Vec3b(0, 0, 0)) top = std::min(top, y), bottom = y;
  EXPECT_EQ(bottom - top + 1, 36);  // rows 6..41: centres 6.5 and 41.5 lie within 24 -+ 17.9
}

TEST(SceneResolution, FitOnTheCommandLineFramesTheModelAsASettingsSceneWithFit) {
  // --fit keeps its meaning of docs/design.md, Camera and transforms: the eye only gives the
  // viewing direction.
  TempDir dir;
  dir.write("sq.obj", "v 1 0 0\nv 3 0 0\nv 3 2 0\nv 1 2 0\nf 1 2 3 4\n");
  dir.write("settings.json", R"({"sq": {"path": "sq.obj", "width": 40, "height": 30,
    "eye": [0.3, 0.2, 5], "fit": true, "shading": "id"}})");
  ASSERT_EQ(test::runZrender({"sq", "-o", dir.file("a.png")}, dir.path).status, 0);
  const auto r = test::runZrender({"sq.obj", "--fit", "--eye", "0.3,0.2,5", "--width", "40",
                                   "--height", "30", "--shading", "id", "-o", dir.file("b.png")},
                                  dir.path);
  ASSERT_EQ(r.status, 0) << r.err;
  const cv::Mat a = test::imread(dir.file("a.png")), b = test::imread(dir.file("b.png"));
  ASSERT_FALSE(a.empty());
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);
  // And it is not the picture from the eye as given: fit moved it.
  ASSERT_EQ(test::runZrender({"sq.obj", "--eye", "0.3,0.2,5", "--width", "40", "--height", "30",
                              "--shading", "id", "-o", dir.file("c.png")},
                             dir.path)
                .status,
            0);
  EXPECT_GT(cv::norm(a, test::imread(dir.file("c.png")), cv::NORM_INF), 0.0);
}

TEST(SceneResolution, NoFitUsesTheCameraAsGivenAndNeedsAnEye) {
  TempDir dir;
  dir.write("sq.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n");
  dir.write("settings.json", R"({"sq": {"path": "sq.obj", "width": 32, "height": 32,
    "eye": [0, 0, 2], "project": [90, 0, 0.1, 100], "shading": "id"}})");
  ASSERT_EQ(test::runZrender({"sq", "-o", dir.file("a.png")}, dir.path).status, 0);
  // The file's defaults for what is not given (target, near 0.1, far 100), no framing.
  const auto r =
      test::runZrender({"sq.obj", "--no-fit", "--eye", "0,0,2", "--fov", "90", "--width", "32",
                        "--height", "32", "--shading", "id", "-o", dir.file("b.png")},
                       dir.path);
  ASSERT_EQ(r.status, 0) << r.err;
  const cv::Mat a = test::imread(dir.file("a.png")), b = test::imread(dir.file("b.png"));
  ASSERT_FALSE(b.empty());
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0.0);

  const auto noEye = test::runZrender({"sq.obj", "--no-fit", "-o", dir.file("c.png")}, dir.path);
  EXPECT_EQ(noEye.status, 2);
  EXPECT_NE(noEye.err.find("'eye'"), std::string::npos) << noEye.err;
  const auto both =
      test::runZrender({"sq.obj", "--no-fit", "--fit", "-o", dir.file("c.png")}, dir.path);
  EXPECT_EQ(both.status, 2);
  EXPECT_NE(both.err.find("--fit excludes --no-fit"), std::string::npos) << both.err;
}

TEST(SceneResolution, WhatFitCannotCompleteIsAnErrorNamingTheModelAndTheOption) {
  TempDir dir;
  dir.write("sq.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n");
  struct Bad {
    std::vector<std::string> args;
    std::vector<std::string> mustName;
  };
  const std::vector<Bad> cases = {
      // Fit puts far at about 6.5 from its eye: a near of 50 lies beyond it.
      {{"--near", "50"}, {"sq.obj", "'project'", "near 50", "--far"}},
      {{"--eye", "0,5,5", "--far", "0.01"}, {"sq.obj", "'project'", "far 0.01", "--near"}},
      // The eye at the model's centre, which fit would make the target.
      {{"--eye", "0,0,0"}, {"sq.obj", "--eye", "centre", "--target"}},
      // Up along the direction from the eye to the centre.
      {{"--eye", "0,3,0"}, {"sq.obj", "--up", "parallel"}},
  };
  for (const Bad& c : cases) {
    std::vector<std::string> args = {"sq.obj", "-o", dir.file("out.png")};
    args.insert(args.end(), c.args.begin(), c.args.end());
    const auto r = test::runZrender(args, dir.path);
    EXPECT_EQ(r.status, 2) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_EQ(r.err.rfind("zrender: error: ", 0), 0u) << r.err;
    for (const auto& piece : c.mustName) EXPECT_NE(r.err.find(piece), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir.file("out.png")));
  }
}

TEST(SceneResolution, DefaultSceneForModel) {
  const SceneSettings s = defaultSceneForModel("models/teapot/teapot.obj");
  EXPECT_EQ(s.name, "teapot");
  EXPECT_EQ(s.modelPath, fs::path("models/teapot/teapot.obj"));
  EXPECT_TRUE(s.fit);
  EXPECT_FALSE(s.eye.has_value());
  EXPECT_EQ(s.width, 1024);
  EXPECT_EQ(s.fovy, 45.0);
  EXPECT_EQ(validateError(s), "no error");
}

}  // namespace
}  // namespace zrender
