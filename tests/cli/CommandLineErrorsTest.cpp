// Errors on the command line end to end (docs/design.md, Errors): one line on stderr naming the
// file and line, the key or the option, exit status 2, and nothing written.

#include <gtest/gtest.h>

#include <filesystem>
#include <iterator>
#include <string>
#include <vector>

#include "support/CommandLineRuns.hpp"
#include "support/TestSupport.hpp"

namespace zrender {
namespace {

namespace fs = std::filesystem;
using test::expectCleanError;
using test::kSquareObj;
using test::runZrender;
using test::settingsFor;
using test::TempDir;

struct BadInput {
  const char* name;
  std::string model;                  // OBJ text
  std::string settingsExtra;          // appended to the scene
  std::vector<std::string> args;      // after the scene name
  std::vector<std::string> mustName;  // pieces of the error line
};

class CommandLineErrors : public ::testing::TestWithParam<BadInput> {};

TEST_P(CommandLineErrors, OneLineExitTwoNoOutput) {
  const BadInput& c = GetParam();
  TempDir dir;
  dir.write("m.obj", c.model);
  dir.write("settings.json", settingsFor("m.obj", c.settingsExtra));
  std::vector<std::string> args = {"sq"};
  args.insert(args.end(), c.args.begin(), c.args.end());
  bool hasOutput = false;
  for (const auto& a : c.args) hasOutput |= a == "-o";
  if (!hasOutput) args.insert(args.end(), {"-o", dir.file("out.png")});
  const auto r = runZrender(args, dir.path);
  expectCleanError(r, c.mustName);
  // Nothing written: only the model and the settings file are in the folder.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator()), 2);
}

INSTANTIATE_TEST_SUITE_P(
    BadInput, CommandLineErrors,
    ::testing::Values(
        BadInput{"MissingModel",
                 kSquareObj,
                 "",
                 {"--settings", "nope.json"},
                 {"nope.json", "cannot open"}},
        BadInput{"MalformedObjLine", "v 0 0 0\nv 1 0 0\nv 0 x 0\nf 1 2 3\n", "", {}, {"m.obj:3"}},
        BadInput{
            "IndexOutOfRange", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n", "", {}, {"m.obj:4", "9"}},
        BadInput{"NanCoordinate", "v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n", "", {}, {"m.obj:2"}},
        BadInput{"EmptyModel", "# nothing\n", "", {}, {"m.obj", "no faces"}},
        BadInput{"WrongKeyType",
                 kSquareObj,
                 R"(, "fit": "yes")",
                 {},
                 {"settings.json", "'sq'", "'fit'"}},
        // A value from the command line: the error names the option as well as the scene.
        BadInput{"SizeOutOfRangeOnCommandLine",
                 kSquareObj,
                 "",
                 {"--width", "0"},
                 {"settings.json: scene 'sq' with --width: key 'width': ", "got 0"}},
        BadInput{"FovNotFinite",
                 kSquareObj,
                 "",
                 {"--fov", "inf"},
                 {"scene 'sq' with --fov: key 'project': ", "[inf, 0, 0.1, 10]"}},
        BadInput{"FarBeforeNearOnCommandLine",
                 kSquareObj,
                 "",
                 {"--near", "1", "--far", "0.5"},
                 {"scene 'sq' with --near, --far: key 'project': ", "near 1 and far 0.5"}},
        BadInput{"AngleNotFinite",
                 kSquareObj,
                 "",
                 {"--angle", "nan"},
                 {"scene 'sq' with --angle: key 'angle': ", "got nan"}},
        // The file's eye is (0, 0, 2): a target there leaves no viewing direction.
        BadInput{"TargetOnTheEye",
                 kSquareObj,
                 "",
                 {"--target", "0,0,2"},
                 {"scene 'sq' with --target: key 'eye': must differ from target [0, 0, 2]"}},
        BadInput{"TurntableWithDepth",
                 kSquareObj,
                 "",
                 {"--turntable", "3", "--depth", "d.tif", "-o", "f%d.png"},
                 {"command line", "--depth", "{view}"}},
        BadInput{"ContactSheetWithoutTurntable",
                 kSquareObj,
                 "",
                 {"--contact-sheet", "sheet.png"},
                 {"command line", "--contact-sheet needs several views"}},
        BadInput{"FramePatternWithAStringDirective",
                 kSquareObj,
                 "",
                 {"--turntable", "2", "-o", "f%5s.png"},
                 {"-o", "{view}", "'f%5s.png'"}},
        BadInput{"UnknownAlgorithm",
                 kSquareObj,
                 "",
                 {"--alg", "raytrace"},
                 {"command line: --alg: unknown algorithm 'raytrace'", "zbuffer"}},
        BadInput{"UnknownShading", kSquareObj, "", {"--shading", "toon"}, {"toon", "phong"}},
        BadInput{"UnsupportedExtension", kSquareObj, "", {"-o", "x.gif"}, {"x.gif", ".png"}},
        BadInput{"UnwritableOutput",
                 kSquareObj,
                 "",
                 {"-o", "/proc/zrender-nope/x.png"},
                 {"/proc/zrender-nope/x.png"}},
        // Outputs are checked before the first one is written: no color image is left
        // behind by a --depth or --ids that cannot be written (m.obj is a file, not a folder).
        BadInput{"DepthUnderAFile",
                 kSquareObj,
                 "",
                 {"-o", "c.png", "--depth", "m.obj/d.png"},
                 {"m.obj/d.png: cannot create folder: "}},
        BadInput{"IdsUnderAFile",
                 kSquareObj,
                 "",
                 {"-o", "c.png", "--ids", "m.obj/i.png"},
                 {"m.obj/i.png: cannot create folder: "}},
        BadInput{"BadOption", kSquareObj, "", {"--frobnicate"}, {"command line", "frobnicate"}},
        BadInput{"MsaaThree", kSquareObj, "", {"--msaa", "3"}, {"msaa"}},
        BadInput{"NoThreads", kSquareObj, "", {"--threads", "0"}, {"--threads", "0"}},
        BadInput{"ThreadsNotANumber", kSquareObj, "", {"--threads", "two"}, {"--threads"}}),
    [](const ::testing::TestParamInfo<BadInput>& p) { return std::string(p.param.name); });

TEST(CommandLineErrors, SizeOutOfRangeInTheFileNamesTheKey) {
  TempDir dir;
  dir.write("sq.obj", kSquareObj);
  dir.write("settings.json", settingsFor("sq.obj", "", "20000"));
  expectCleanError(runZrender({"sq"}, dir.path), {"settings.json", "'sq'", "'width'", "16384"});
}

TEST(CommandLineErrors, BadJsonNamesTheLine) {
  TempDir dir;
  dir.write("settings.json", "{\n  \"sq\": {\n    \"path\": \"m.obj\",,\n  }\n}\n");
  expectCleanError(runZrender({"sq"}, dir.path), {"settings.json", "line 3"});
}

TEST(CommandLineErrors, UnknownSceneListsTheScenes) {
  TempDir dir;
  dir.write("sq.obj", kSquareObj);
  dir.write("settings.json", settingsFor("sq.obj"));
  expectCleanError(runZrender({"cube"}, dir.path), {"settings.json", "cube", "sq"});
}

}  // namespace
}  // namespace zrender
