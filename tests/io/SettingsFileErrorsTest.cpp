// Errors in the settings file (docs/design.md, Settings and Errors): bad and non-strict JSON,
// wrong types and values of every key family, each named in one line that quotes the value
// (shortened and flattened) and never writes control characters.

#include <gtest/gtest.h>

#include <string>

#include "support/SettingsParsing.hpp"

namespace zrender {
namespace {

namespace fs = std::filesystem;
using test::bunnyError;
using test::bunnyWith;
using test::parse;
using test::parseError;

TEST(SettingsFileErrors, BadJsonNamesLineAndColumnOnOneLine) {
  // The comma after "x" is missing; jsoncpp stops at the next member name, line 3, column 3.
  const std::string message = parseError("{\"a\": {\"path\": \"x\"\n\n  \"b\": 1}}");
  EXPECT_EQ(message.rfind("settings.json: bad JSON: line 3, column 3: ", 0), 0u) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(SettingsFileErrors, StrictJson) {
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

TEST(SettingsFileErrors, ByteOrderMarkIsSkippedAndExcerptsStayAligned) {
  EXPECT_EQ(
      parseError("\xEF\xBB\xBF" + bunnyWith(R"("width": 0)")),
      "settings.json: scene 'bunny': key 'width': expected an integer from 1 to 16384, got 0");
}

TEST(SettingsFileErrors, DeepNestingIsACleanError) {
  const std::string text =
      R"({"a": {"path": "x", "junk": )" + std::string(5000, '[') + std::string(5000, ']') + "}}";
  EXPECT_EQ(parseError(text), "settings.json: bad JSON: nested deeper than 64 levels");
}

TEST(SettingsFileErrors, TopLevelAndSceneMustBeObjects) {
  EXPECT_EQ(parseError(R"([{"path": "x"}])"),
            "settings.json: expected a JSON object of scenes at the top level, got an array");
  EXPECT_EQ(parseError(R"({"bunny": 3})"),
            "settings.json: scene 'bunny': expected an object of scene keys, got 3");
  EXPECT_EQ(
      parseError(R"({"bunny": ["path", "x"]})"),
      "settings.json: scene 'bunny': expected an object of scene keys, got [\"path\", \"x\"]");
}

TEST(SettingsFileErrors, MissingPath) {
  EXPECT_EQ(parseError(R"({"bunny": {"width": 10}})"),
            "settings.json: scene 'bunny': key 'path': missing");
}

TEST(SettingsFileErrors, SizeRange) {
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

TEST(SettingsFileErrors, WrongTypePerKeyFamily) {
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

TEST(SettingsFileErrors, LongValuesAreShortenedAndFlattened) {
  // Flattened, the array reads "[1, 2, ..."; its first 60 characters are "[1, " .. "9, " (28)
  // and "10, " .. "17, " (8 x 4 = 32); the trailing space goes before the ellipsis.
  const std::string message = bunnyError(
      "\"eye\": [1,\n 2,\n 3,\n 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20]");
  EXPECT_EQ(message,
            "settings.json: scene 'bunny': key 'eye': expected an array of 3 finite numbers, got "
            "[1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17,...");
}

TEST(SettingsFileErrors, ProjectionRange) {
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

TEST(SettingsFileErrors, ShadingMsaaBackgroundGrid) {
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

TEST(SettingsFileErrors, ZeroDirectionsAreErrors) {
  EXPECT_EQ(bunnyError(R"("axis": [0, 0, 0])"),
            "settings.json: scene 'bunny': key 'axis': must have a non-zero length, got [0, 0, 0]");
  EXPECT_EQ(bunnyError(R"("up": [0, 0, 0])"),
            "settings.json: scene 'bunny': key 'up': must have a non-zero length, got [0, 0, 0]");
}

TEST(SettingsFileErrors, MessagesStayOnOneLine) {
  EXPECT_EQ(parseError(R"({"a\nb": {"width": 1}})"),
            "settings.json: scene 'a\\nb': key 'path': missing");
  // Other control characters are shown as escapes, never written raw to the terminal.
  EXPECT_EQ(parseError(R"({"a\tb\u0001c\u007f": {"width": 1}})"),
            "settings.json: scene 'a\\tb\\x01c\\x7f': key 'path': missing");
}

}  // namespace
}  // namespace zrender
