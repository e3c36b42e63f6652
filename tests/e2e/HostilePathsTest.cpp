// Hostile output paths end to end (docs/design.md, Errors): outputs that cannot be written
// leave nothing behind, and an existing output is replaced only by a complete file.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "support/HostileRuns.hpp"

namespace zrender {
namespace {

namespace fs = std::filesystem;
using namespace test;

TEST(HostilePaths, ImpossiblePathsLeaveNothingBehind) {
  TempDir dir;
  dir.write("m.obj", kSquareObj);
  dir.write("file", "a regular file\n");
  fs::create_directory(dir.file("folder.png"));
  const std::vector<std::string> before = listFolder(dir.path);
  const std::vector<std::pair<std::string, std::string>> outputs = {
      {"/proc/zrender-nope/x.png", "/proc/zrender-nope/x.png"},
      {"file/x.png", "file/x.png"},                // parent is a regular file
      {"file/deeper/x.png", "file/deeper/x.png"},  // an ancestor is
      {"folder.png", "folder.png"},                // the output is a folder
      {"/proc/self/status.png", "/proc/self/status.png"},
  };
  for (const auto& [output, named] : outputs) {
    SCOPED_TRACE(output);
    const Outcome r =
        runLimited({"m.obj", "-o", output, "--width", "8", "--height", "8"}, dir.path);
    expectQuickCleanError(r, {named});
    EXPECT_EQ(listFolder(dir.path), before);  // no output, no temporary file
    EXPECT_TRUE(fs::is_directory(dir.file("folder.png")));
    EXPECT_TRUE(fs::is_empty(dir.file("folder.png")));
  }
}

TEST(HostilePaths, ExistingOutputIsReplacedOnlyByACompleteFile) {
  TempDir dir;
  dir.write("m.obj", kSquareObj);
  const std::string old = "the previous picture\n";
  dir.write("out.png", old);
  const std::vector<std::string> before = listFolder(dir.path);
  // Random colors do not compress: a 256 x 256 PNG is far above the 4 KB file size limit, so
  // writing stops part way with EFBIG.
  const std::vector<std::string> args = {"m.obj",  "-o",       "out.png", "--width",
                                         "256",    "--height", "256",     "--shading",
                                         "random", "--msaa",   "4"};
  dir.write("m.obj", gridModel(40, 40));
  const Outcome failed = runLimited(args, dir.path, 60, 4096);
  expectQuickCleanError(failed, {"out.png"});
  EXPECT_EQ(readFile(dir.file("out.png")), old);
  EXPECT_EQ(listFolder(dir.path), before);

  // A failed render (bad model) leaves it alone too.
  dir.write("m.obj", "v 0 0 0\nf 1 2 3\n");
  expectQuickCleanError(runLimited(args, dir.path), {"m.obj"});
  EXPECT_EQ(readFile(dir.file("out.png")), old);

  // A successful one replaces it with a complete picture.
  dir.write("m.obj", gridModel(40, 40));
  const cv::Mat image = expectPicture(runLimited(args, dir.path), dir.file("out.png"), 256, 256);
  EXPECT_GT(coveredPixels(image), 256 * 64);
  EXPECT_EQ(listFolder(dir.path), before);
}

}  // namespace
}  // namespace zrender
