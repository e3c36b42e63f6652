// The settings file (docs/design.md, Settings): every key parsed, the documented defaults,
// paths resolved against the file's folder, unknown keys warned about, and files loaded or
// refused (missing, a folder, too large).

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/SettingsParsing.hpp"
#include "zrender/base/Error.hpp"
#include "zrender/io/settings/SettingsFile.hpp"
#include "zrender/scene/SceneValidation.hpp"

namespace zrender {
namespace {

namespace fs = std::filesystem;
using test::bunnyError;
using test::bunnyWith;
using test::parse;
using test::parseError;

fs::path uniqueTempPath(const std::string& stem) {
  const auto ticks = std::chrono::steady_clock::now().time_since_epoch().count();
  return fs::temp_directory_path() /
         (stem + "-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
          std::to_string(ticks));
}

TEST(SettingsFile, FullSceneParsesEveryKey) {
  const std::string text = R"({
    "spot": {
      "path": "models/spot/spot.obj",
      "width": 640, "height": 480,
      "eye": [1.5, -2, 3.25], "target": [0.5, 0.25, -1], "up": [0, 0, 1],
      "angle": 37.5, "axis": [1, 0, 0],
      "project": [60, 1.5, 0.5, 20],
      "fit": true, "shading": "texture", "msaa": 4, "cull": false,
      "texture": "tex/spot.png",
      "background": [10, 20, 255],
      "grid": {"count": [3, 2, 1], "spacing": [2.5, -1, 0]},
      "bench": true
    }
  })";
  Warnings warnings;
  const SettingsFile file = parse(text, warnings, "/data/proj/settings.json");
  EXPECT_TRUE(warnings.empty());
  EXPECT_EQ(file.path, fs::path("/data/proj/settings.json"));
  ASSERT_EQ(file.scenes.size(), 1u);
  const SceneSettings& s = file.scenes.at("spot");
  EXPECT_EQ(s.name, "spot");
  EXPECT_EQ(s.modelPath, fs::path("/data/proj/models/spot/spot.obj"));
  EXPECT_EQ(s.width, 640);
  EXPECT_EQ(s.height, 480);
  ASSERT_TRUE(s.eye.has_value());
  EXPECT_EQ(*s.eye, cv::Vec3d(1.5, -2, 3.25));
  EXPECT_EQ(s.target, cv::Vec3d(0.5, 0.25, -1));
  EXPECT_EQ(s.up, cv::Vec3d(0, 0, 1));
  EXPECT_EQ(s.angle, 37.5);
  EXPECT_EQ(s.axis, cv::Vec3d(1, 0, 0));
  EXPECT_EQ(s.fovy, 60.0);
  EXPECT_EQ(s.aspect, 1.5);
  EXPECT_EQ(s.near, 0.5);
  EXPECT_EQ(s.far, 20.0);
  EXPECT_TRUE(s.fit);
  EXPECT_EQ(s.shading, ShadingMode::Texture);
  EXPECT_EQ(s.msaa, 4);
  EXPECT_FALSE(s.cull);
  ASSERT_TRUE(s.texture.has_value());
  EXPECT_EQ(*s.texture, fs::path("/data/proj/tex/spot.png"));
  EXPECT_EQ(s.background, (std::array<int, 3>{10, 20, 255}));
  ASSERT_TRUE(s.grid.has_value());
  EXPECT_EQ(s.grid->count, (std::array<int, 3>{3, 2, 1}));
  EXPECT_EQ(s.grid->spacing, cv::Vec3d(2.5, -1, 0));
  EXPECT_EQ(s.grid->instanceCount(), 6);
  EXPECT_TRUE(s.bench);
  EXPECT_NO_THROW(validateScene(s, "x"));
}

TEST(SettingsFile, AbsentKeysTakeTheDocumentedDefaults) {
  const SettingsFile file = parse(R"({"a": {"path": "a.obj"}, "b": {"path": "b.obj"}})");
  ASSERT_EQ(file.scenes.size(), 2u);
  const SceneSettings& s = file.scenes.at("a");
  EXPECT_EQ(s.name, "a");
  EXPECT_EQ(s.modelPath, fs::path("a.obj"));
  EXPECT_EQ(s.width, 1024);
  EXPECT_EQ(s.height, 1024);
  EXPECT_FALSE(s.eye.has_value());
  EXPECT_EQ(s.target, cv::Vec3d(0, 0, 0));
  EXPECT_EQ(s.up, cv::Vec3d(0, 1, 0));
  EXPECT_EQ(s.angle, 0.0);
  EXPECT_EQ(s.axis, cv::Vec3d(0, 1, 0));
  EXPECT_EQ(s.fovy, 45.0);
  EXPECT_EQ(s.aspect, 0.0);
  EXPECT_EQ(s.near, 0.1);
  EXPECT_EQ(s.far, 100.0);
  EXPECT_FALSE(s.fit);
  EXPECT_EQ(s.shading, ShadingMode::Normal);
  EXPECT_EQ(s.msaa, 1);
  EXPECT_TRUE(s.cull);
  EXPECT_FALSE(s.texture.has_value());
  EXPECT_EQ(s.background, (std::array<int, 3>{0, 0, 0}));
  EXPECT_FALSE(s.grid.has_value());
  EXPECT_FALSE(s.bench);
  EXPECT_EQ(file.scenes.at("b").modelPath, fs::path("b.obj"));
}

TEST(SettingsFile, SeedProjectWithNegativeNearFar) {
  // The seed's bunny entry, verbatim.
  const SettingsFile file = parse(R"({
    "bunny": {
      "path": "models/bunny/bunny.obj",
      "width": 1800, "height": 1800,
      "eye": [-0.5, 0.8, 10.0],
      "angle": 0.0, "axis": [0.0, 1.0, 0.0],
      "project": [30.0, 1.0, -1.0, -50.0]
    }
  })");
  const SceneSettings& s = file.scenes.at("bunny");
  EXPECT_EQ(s.fovy, 30.0);
  EXPECT_EQ(s.aspect, 1.0);
  EXPECT_EQ(s.near, 1.0);
  EXPECT_EQ(s.far, 50.0);
  EXPECT_EQ(s.width, 1800);
  EXPECT_EQ(*s.eye, cv::Vec3d(-0.5, 0.8, 10.0));
  EXPECT_NO_THROW(validateScene(s, "settings.json: scene 'bunny'"));
}

TEST(SettingsFile, GridDefaultsForAbsentMembers) {
  const SceneSettings s = parse(bunnyWith(R"("grid": {"count": [2, 1, 4]})")).scenes.at("bunny");
  ASSERT_TRUE(s.grid.has_value());
  EXPECT_EQ(s.grid->count, (std::array<int, 3>{2, 1, 4}));
  EXPECT_EQ(s.grid->spacing, cv::Vec3d(0, 0, 0));
}

TEST(SettingsFile, IntegralRealsAreIntegers) {
  EXPECT_EQ(parse(bunnyWith(R"("width": 800.0)")).scenes.at("bunny").width, 800);
}

TEST(SettingsFile, PathsResolveAgainstTheSettingsFolder) {
  const std::string text = R"({"s": {"path": "models/x.obj", "texture": "t.png"}})";
  Warnings warnings;
  EXPECT_EQ(parse(text, warnings, "settings.json").scenes.at("s").modelPath,
            fs::path("models/x.obj"));
  const SceneSettings nested = parse(text, warnings, "sub/dir/s.json").scenes.at("s");
  EXPECT_EQ(nested.modelPath, fs::path("sub/dir/models/x.obj"));
  EXPECT_EQ(*nested.texture, fs::path("sub/dir/t.png"));
  EXPECT_EQ(
      parse(R"({"s": {"path": "/abs/m.obj"}})", warnings, "sub/s.json").scenes.at("s").modelPath,
      fs::path("/abs/m.obj"));
}

TEST(SettingsFile, UnknownKeysWarn) {
  Warnings warnings;
  const SettingsFile file =
      parse(bunnyWith(R"("colour": [1, 2, 3], "grid": {"count": [1, 1, 1], "step": 2})"), warnings);
  EXPECT_EQ(file.scenes.size(), 1u);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0], "settings.json: scene 'bunny': unknown key 'colour' (ignored)");
  EXPECT_EQ(warnings[1], "settings.json: scene 'bunny': unknown key 'grid.step' (ignored)");
}

TEST(SettingsFile, LoadSettingsFromFile) {
  const fs::path folder = uniqueTempPath("zrender-settings");
  ASSERT_TRUE(fs::create_directories(folder));
  const fs::path file = folder / "scenes.json";
  {
    std::ofstream out(file);
    out << R"({"teapot": {"path": "teapot.obj", "width": 32, "oops": 1}})";
  }
  Warnings warnings;
  const SettingsFile settings = loadSettings(file, warnings);
  fs::remove_all(folder);
  EXPECT_EQ(settings.path, file);
  EXPECT_EQ(settings.scenes.at("teapot").modelPath, folder / "teapot.obj");
  EXPECT_EQ(settings.scenes.at("teapot").width, 32);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], file.string() + ": scene 'teapot': unknown key 'oops' (ignored)");
}

TEST(SettingsFile, LoadSettingsRefusesAHugeFile) {
  const fs::path folder = uniqueTempPath("zrender-settings");
  ASSERT_TRUE(fs::create_directories(folder));
  const fs::path file = folder / "settings.json";
  {
    // 64 MiB of white space and one more byte: over the limit before any JSON is parsed.
    std::ofstream out(file, std::ios::binary);
    const std::string block(1 << 20, ' ');
    for (int i = 0; i < 64; ++i) out << block;
    out << "{";
  }
  Warnings warnings;
  std::string message = "no error";
  try {
    loadSettings(file, warnings);
  } catch (const InputError& e) {
    message = e.what();
  }
  fs::remove_all(folder);
  EXPECT_EQ(message, file.string() + ": file too large for a settings file (over 64 MiB)");
}

TEST(SettingsFile, LoadSettingsMissingFile) {
  const fs::path missing = uniqueTempPath("zrender-missing") / "settings.json";
  Warnings warnings;
  try {
    loadSettings(missing, warnings);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), missing.string() + ": cannot open file");
  }
  try {
    loadSettings(fs::temp_directory_path(), warnings);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              fs::temp_directory_path().string() + ": cannot open file (it is a folder)");
  }
}

}  // namespace
}  // namespace zrender

namespace zrender {
namespace {

TEST(SettingsFile, ViewsInFullOrRelative) {
  Warnings warnings;
  const SettingsFile file = test::parse(test::bunnyWith(R"("views": [
      {"azimuth": 30, "elevation": -10.5, "zoom": 2},
      {"eye": [1, 2, 3], "target": [0, 1, 0], "up": [0, 0, 1]},
      {}, {"tilt": 3}])"),
                                        warnings);
  const std::vector<ViewSpec>& views = file.scenes.at("bunny").views;
  ASSERT_EQ(views.size(), 4u);
  EXPECT_EQ(views[0].azimuth, 30.0);
  EXPECT_EQ(views[0].elevation, -10.5);
  EXPECT_EQ(views[0].zoom, 2.0);
  EXPECT_FALSE(views[0].givesCamera());
  EXPECT_EQ(*views[1].eye, cv::Vec3d(1, 2, 3));
  EXPECT_EQ(*views[1].target, cv::Vec3d(0, 1, 0));
  EXPECT_EQ(*views[1].up, cv::Vec3d(0, 0, 1));
  EXPECT_EQ(views[2].zoom, 1.0);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], "settings.json: scene 'bunny': unknown key 'views[3].tilt' (ignored)");
}

TEST(SettingsFile, BadViewsNameTheKey) {
  const std::string where = "settings.json: scene 'bunny': key ";
  EXPECT_EQ(test::bunnyError(R"("views": [])"),
            where + "'views': expected a non-empty array of views, got []");
  EXPECT_EQ(test::bunnyError(R"("views": [{}, 3])"),
            where +
                "'views[1]': expected an object of eye, target, up, azimuth, elevation, "
                "zoom, got 3");
  EXPECT_EQ(test::bunnyError(R"("views": [{"zoom": 0}])"),
            where + "'views[0].zoom': expected a number above 0, got 0");
  EXPECT_EQ(test::bunnyError(R"("views": [{"azimuth": "east"}])"),
            where + "'views[0].azimuth': expected a finite number, got \"east\"");
  EXPECT_EQ(test::bunnyError(R"("views": [{"eye": [1, 2]}])"),
            where + "'views[0].eye': expected an array of 3 finite numbers, got [1, 2]");
  EXPECT_NE(test::bunnyError(R"("views": [{"up": [0, 0, 0]}])").find("'views[0].up'"),
            std::string::npos);
}

}  // namespace
}  // namespace zrender
