#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "zrender/base/Error.hpp"
#include "zrender/cli/SceneResolution.hpp"
#include "zrender/io/SceneValidation.hpp"
#include "zrender/io/SettingsFile.hpp"
#include "zrender/scene/ShadingMode.hpp"

namespace zrender {
namespace {

namespace fs = std::filesystem;

SettingsFile parse(const std::string& text, Warnings& warnings,
                   const fs::path& path = "settings.json") {
  return parseSettings(text, path, warnings);
}

SettingsFile parse(const std::string& text) {
  Warnings warnings;
  return parse(text, warnings);
}

// The message of the InputError that parsing throws, or "no error".
std::string parseError(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// A scene "bunny" with a valid path plus the given members.
std::string bunnyWith(const std::string& members) {
  return R"({"bunny": {"path": "m.obj", )" + members + "}}";
}

std::string bunnyError(const std::string& members) {
  return parseError(bunnyWith(members));
}

std::string validateError(const SceneSettings& scene) {
  try {
    validateScene(scene, "command line");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

// A scene that passes validateScene: eye on +z looking at the origin.
SceneSettings validScene() {
  SceneSettings scene;
  scene.name = "s";
  scene.modelPath = "m.obj";
  scene.eye = cv::Vec3d(0, 0, 5);
  return scene;
}

fs::path uniqueTempPath(const std::string& stem) {
  const auto ticks = std::chrono::steady_clock::now().time_since_epoch().count();
  return fs::temp_directory_path() /
         (stem + "-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "-" +
          std::to_string(ticks));
}

TEST(ShadingTest, NamesInSpecOrderAndRoundTrip) {
  const std::vector<std::string> expected{"normal",  "flat", "phong", "random",
                                          "texture", "id",   "depth"};
  EXPECT_EQ(shadingModeNames(), expected);
  EXPECT_EQ(parseShadingMode("normal"), ShadingMode::Normal);
  EXPECT_EQ(parseShadingMode("texture"), ShadingMode::Texture);
  EXPECT_EQ(parseShadingMode("depth"), ShadingMode::Depth);
  EXPECT_EQ(shadingModeName(ShadingMode::Flat), "flat");
  EXPECT_EQ(shadingModeName(ShadingMode::Id), "id");
  for (const auto& name : expected) {
    const auto mode = parseShadingMode(name);
    ASSERT_TRUE(mode.has_value()) << name;
    EXPECT_EQ(shadingModeName(*mode), name);
  }
}

TEST(ShadingTest, UnknownNamesAreRejected) {
  EXPECT_FALSE(parseShadingMode("gouraud").has_value());
  EXPECT_FALSE(parseShadingMode("Normal").has_value());  // names are case-sensitive
  EXPECT_FALSE(parseShadingMode("").has_value());
}

TEST(SettingsTest, FullSceneParsesEveryKey) {
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

TEST(SettingsTest, AbsentKeysTakeTheSpecDefaults) {
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

TEST(SettingsTest, SeedProjectWithNegativeNearFar) {
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

TEST(SettingsTest, GridDefaultsForAbsentMembers) {
  const SceneSettings s = parse(bunnyWith(R"("grid": {"count": [2, 1, 4]})")).scenes.at("bunny");
  ASSERT_TRUE(s.grid.has_value());
  EXPECT_EQ(s.grid->count, (std::array<int, 3>{2, 1, 4}));
  EXPECT_EQ(s.grid->spacing, cv::Vec3d(0, 0, 0));
}

TEST(SettingsTest, IntegralRealsAreIntegers) {
  EXPECT_EQ(parse(bunnyWith(R"("width": 800.0)")).scenes.at("bunny").width, 800);
}

TEST(SettingsTest, PathsResolveAgainstTheSettingsFolder) {
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

TEST(SettingsTest, BadJsonNamesLineAndColumnOnOneLine) {
  // The comma after "x" is missing; jsoncpp stops at the next member name, line 3, column 3.
  const std::string message = parseError("{\"a\": {\"path\": \"x\"\n\n  \"b\": 1}}");
  EXPECT_EQ(message.rfind("settings.json: bad JSON: line 3, column 3: ", 0), 0u) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(SettingsTest, StrictJson) {
  EXPECT_EQ(parseError(R"({"a": {"path": "x",}})").rfind("settings.json: bad JSON: line 1, ", 0),
            0u);
  EXPECT_EQ(parseError(R"({"a": {"path": "x"}} trailing)"),
            "settings.json: bad JSON: line 1, column 22: Extra non-whitespace after JSON value.");
  const std::string duplicate = parseError(R"({"a": {"path": "x", "path": "y"}})");
  EXPECT_NE(duplicate.find("bad JSON: line 1, column 21: Duplicate key: 'path'"), std::string::npos)
      << duplicate;
  EXPECT_EQ(
      parseError(R"({"a": {"path": "x", "angle": NaN}})").rfind("settings.json: bad JSON:", 0), 0u);
  EXPECT_EQ(parseError("").rfind("settings.json: bad JSON: line 1, column 1: ", 0), 0u);
  // Comments are allowed.
  EXPECT_EQ(parse("// scenes\n{\"a\": {\"path\": \"x\" /* model */}}").scenes.size(), 1u);
}

TEST(SettingsTest, ByteOrderMarkIsSkippedAndExcerptsStayAligned) {
  EXPECT_EQ(
      parseError("\xEF\xBB\xBF" + bunnyWith(R"("width": 0)")),
      "settings.json: scene 'bunny': key 'width': expected an integer from 1 to 16384, got 0");
}

TEST(SettingsTest, DeepNestingIsACleanError) {
  const std::string text =
      R"({"a": {"path": "x", "junk": )" + std::string(5000, '[') + std::string(5000, ']') + "}}";
  EXPECT_EQ(parseError(text), "settings.json: bad JSON: nested deeper than 64 levels");
}

TEST(SettingsTest, TopLevelAndSceneMustBeObjects) {
  EXPECT_EQ(parseError(R"([{"path": "x"}])"),
            "settings.json: expected a JSON object of scenes at the top level, got an array");
  EXPECT_EQ(parseError(R"({"bunny": 3})"),
            "settings.json: scene 'bunny': expected an object of scene keys, got 3");
  EXPECT_EQ(
      parseError(R"({"bunny": ["path", "x"]})"),
      "settings.json: scene 'bunny': expected an object of scene keys, got [\"path\", \"x\"]");
}

TEST(SettingsTest, MissingPath) {
  EXPECT_EQ(parseError(R"({"bunny": {"width": 10}})"),
            "settings.json: scene 'bunny': key 'path': missing");
}

TEST(SettingsTest, SizeRange) {
  EXPECT_EQ(
      bunnyError(R"("width": 0)"),
      "settings.json: scene 'bunny': key 'width': expected an integer from 1 to 16384, got 0");
  EXPECT_EQ(bunnyError(R"("height": 16385)"),
            "settings.json: scene 'bunny': key 'height': expected an integer from 1 to 16384, "
            "got 16385");
  EXPECT_EQ(bunnyError(R"("width": 10.5)"),
            "settings.json: scene 'bunny': key 'width': expected an integer from 1 to 16384, "
            "got 10.5");
  EXPECT_EQ(parse(bunnyWith(R"("width": 16384, "height": 1)")).scenes.at("bunny").width, 16384);
}

TEST(SettingsTest, WrongTypePerKeyFamily) {
  const std::string prefix = "settings.json: scene 'bunny': key ";
  EXPECT_EQ(parseError(R"({"bunny": {"path": 5}})"),
            prefix + "'path': expected a string (a file path), got 5");
  EXPECT_EQ(bunnyError(R"("width": "1024")"),
            prefix + "'width': expected an integer from 1 to 16384, got \"1024\"");
  EXPECT_EQ(bunnyError(R"("eye": [1, 2])"),
            prefix + "'eye': expected an array of 3 finite numbers, got [1, 2]");
  EXPECT_EQ(bunnyError(R"("target": [1, "2", 3])"),
            prefix + "'target': expected an array of 3 finite numbers, got [1, \"2\", 3]");
  EXPECT_EQ(bunnyError(R"("angle": "90")"),
            prefix + "'angle': expected a finite number, got \"90\"");
  EXPECT_EQ(bunnyError(R"("project": [30, 1, 1])"),
            prefix +
                "'project': expected [fovy, aspect, near, far] (4 finite numbers), got "
                "[30, 1, 1]");
  EXPECT_EQ(bunnyError(R"("fit": 1)"), prefix + "'fit': expected true or false, got 1");
  EXPECT_EQ(bunnyError(R"("bench": "yes")"),
            prefix + "'bench': expected true or false, got \"yes\"");
  EXPECT_EQ(bunnyError(R"("cull": null)"), prefix + "'cull': expected true or false, got null");
  EXPECT_EQ(bunnyError(R"("texture": [1])"),
            prefix + "'texture': expected a string (a file path), got [1]");
  EXPECT_EQ(bunnyError(R"("grid": 3)"),
            prefix +
                "'grid': expected an object {\"count\": [nx, ny, nz], \"spacing\": [sx, sy, "
                "sz]}, got 3");
  EXPECT_EQ(bunnyError(R"("grid": {"spacing": [1, 2]})"),
            prefix + "'grid.spacing': expected an array of 3 finite numbers, got [1, 2]");
}

TEST(SettingsTest, LongValuesAreShortenedAndFlattened) {
  // Flattened, the array reads "[1, 2, ..."; its first 60 characters are "[1, " .. "9, " (28)
  // and "10, " .. "17, " (8 x 4 = 32); the trailing space goes before the ellipsis.
  const std::string message = bunnyError(
      "\"eye\": [1,\n 2,\n 3,\n 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20]");
  EXPECT_EQ(message,
            "settings.json: scene 'bunny': key 'eye': expected an array of 3 finite numbers, got "
            "[1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17,...");
}

TEST(SettingsTest, ProjectionRange) {
  const std::string prefix = "settings.json: scene 'bunny': key 'project': ";
  EXPECT_EQ(bunnyError(R"("project": [0, 1, 1, 50])"),
            prefix + "fovy must be greater than 0 and less than 180 degrees, got 0");
  EXPECT_EQ(bunnyError(R"("project": [180, 1, 1, 50])"),
            prefix + "fovy must be greater than 0 and less than 180 degrees, got 180");
  EXPECT_EQ(bunnyError(R"("project": [30, 1, -5, 5])"),
            prefix + "far must be greater than near, got near 5 and far 5");
  EXPECT_EQ(bunnyError(R"("project": [30, 1, 0.25, -0.1])"),
            prefix + "far must be greater than near, got near 0.25 and far 0.1");
  EXPECT_EQ(bunnyError(R"("project": [30, 1, 0, 5])"),
            prefix + "near must be greater than 0, got 0");
  EXPECT_EQ(bunnyError(R"("project": [30, 1, 0.1, 1e999])"),
            "settings.json: bad JSON: line 1, column 53: '1e999' is not a number.");
}

TEST(SettingsTest, ShadingMsaaBackgroundGrid) {
  const std::string prefix = "settings.json: scene 'bunny': key ";
  EXPECT_EQ(bunnyError(R"("shading": "gouraud")"),
            prefix +
                "'shading': expected one of normal, flat, phong, random, texture, id, depth, "
                "got \"gouraud\"");
  EXPECT_EQ(bunnyError(R"("msaa": 3)"), prefix + "'msaa': expected 1 or 4, got 3");
  EXPECT_EQ(
      bunnyError(R"("background": [0, 0, 256])"),
      prefix + "'background': expected an array of 3 integers from 0 to 255, got [0, 0, 256]");
  EXPECT_EQ(
      bunnyError(R"("grid": {"count": [0, 1, 1]})"),
      prefix + "'grid.count': expected an array of 3 integers from 1 to 1000000, got [0, 1, 1]");
  EXPECT_EQ(
      bunnyError(R"("grid": {"count": [1000, 1000, 2]})"),
      prefix + "'grid.count': at most 1000000 instances in all, got 1000 x 1000 x 2 = 2000000");
}

TEST(SettingsTest, ZeroDirectionsAreErrors) {
  EXPECT_EQ(bunnyError(R"("axis": [0, 0, 0])"),
            "settings.json: scene 'bunny': key 'axis': must have a non-zero length, got [0, 0, 0]");
  EXPECT_EQ(bunnyError(R"("up": [0, 0, 0])"),
            "settings.json: scene 'bunny': key 'up': must have a non-zero length, got [0, 0, 0]");
}

TEST(SettingsTest, UnknownKeysWarn) {
  Warnings warnings;
  const SettingsFile file =
      parse(bunnyWith(R"("colour": [1, 2, 3], "grid": {"count": [1, 1, 1], "step": 2})"), warnings);
  EXPECT_EQ(file.scenes.size(), 1u);
  ASSERT_EQ(warnings.size(), 2u);
  EXPECT_EQ(warnings[0], "settings.json: scene 'bunny': unknown key 'colour' (ignored)");
  EXPECT_EQ(warnings[1], "settings.json: scene 'bunny': unknown key 'grid.step' (ignored)");
}

TEST(SettingsTest, MessagesStayOnOneLine) {
  EXPECT_EQ(parseError(R"({"a\nb": {"width": 1}})"),
            "settings.json: scene 'a\\nb': key 'path': missing");
  // Other control characters are shown as escapes, never written raw to the terminal.
  EXPECT_EQ(parseError(R"({"a\tb\u0001c\u007f": {"width": 1}})"),
            "settings.json: scene 'a\\tb\\x01c\\x7f': key 'path': missing");
}

TEST(SettingsTest, ValidateSceneEyeRules) {
  EXPECT_EQ(validateError(validScene()), "no error");

  SceneSettings noEye = validScene();
  noEye.eye.reset();
  EXPECT_EQ(validateError(noEye), "command line: key 'eye': missing (required unless fit is on)");
  noEye.fit = true;
  EXPECT_EQ(validateError(noEye), "no error");

  SceneSettings same = validScene();
  same.eye = cv::Vec3d(1, 2, 3);
  same.target = cv::Vec3d(1, 2, 3);
  EXPECT_EQ(validateError(same),
            "command line: key 'eye': must differ from target [1, 2, 3], got [1, 2, 3]");

  SceneSettings parallel = validScene();  // looks down -z
  parallel.up = cv::Vec3d(0, 0, -2);
  EXPECT_EQ(validateError(parallel),
            "command line: key 'up': must not be parallel to the viewing direction target - eye "
            "[0, 0, -5], got [0, 0, -2]");
  parallel.up = cv::Vec3d(0, 0.01, 1);  // nearly but not exactly parallel is allowed
  EXPECT_EQ(validateError(parallel), "no error");
}

TEST(SettingsTest, ValidateSceneRanges) {
  SceneSettings s = validScene();
  s.width = 0;
  EXPECT_EQ(validateError(s),
            "command line: key 'width': expected an integer from 1 to 16384, got 0");
  s = validScene();
  s.fovy = 180;
  EXPECT_EQ(validateError(s),
            "command line: key 'project': fovy must be greater than 0 and less than 180 degrees, "
            "got 180");
  s = validScene();
  s.near = 2;
  s.far = 2;
  EXPECT_EQ(validateError(s),
            "command line: key 'project': far must be greater than near, got "
            "near 2 and far 2");
  s = validScene();
  s.msaa = 2;
  EXPECT_EQ(validateError(s), "command line: key 'msaa': expected 1 or 4, got 2");
  s = validScene();
  s.up = cv::Vec3d(0, 0, 0);
  EXPECT_EQ(validateError(s), "command line: key 'up': must have a non-zero length, got [0, 0, 0]");
  s = validScene();
  s.axis = cv::Vec3d(0, std::numeric_limits<double>::infinity(), 0);
  EXPECT_EQ(validateError(s),
            "command line: key 'axis': expected 3 finite numbers, got [0, inf, 0]");
  s = validScene();
  s.eye = cv::Vec3d(0, std::nan(""), 5);
  EXPECT_EQ(validateError(s),
            "command line: key 'eye': expected 3 finite numbers, got [0, nan, 5]");
}

TEST(SettingsTest, DefaultSceneForModel) {
  const SceneSettings s = defaultSceneForModel("models/teapot/teapot.obj");
  EXPECT_EQ(s.name, "teapot");
  EXPECT_EQ(s.modelPath, fs::path("models/teapot/teapot.obj"));
  EXPECT_TRUE(s.fit);
  EXPECT_FALSE(s.eye.has_value());
  EXPECT_EQ(s.width, 1024);
  EXPECT_EQ(s.fovy, 45.0);
  EXPECT_EQ(validateError(s), "no error");
}

TEST(SettingsTest, LoadSettingsFromFile) {
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

TEST(SettingsTest, LoadSettingsRefusesAHugeFile) {
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

TEST(SettingsTest, LoadSettingsMissingFile) {
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
