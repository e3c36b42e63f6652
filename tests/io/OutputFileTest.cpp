// Outputs written completely or not at all (OutputFile): inside a private folder of a random
// name, never through a link planted for it, renamed over the target, and nothing left behind
// on failure.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <iterator>
#include <string>
#include <system_error>
#include <vector>

#include "support/TestSupport.hpp"
#include "zrender/base/Error.hpp"
#include "zrender/io/files/OutputFile.hpp"
#include "zrender/io/images/ImageOutput.hpp"

namespace zrender {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

std::vector<std::string> names(const fs::path& folder) {
  std::vector<std::string> out;
  for (const auto& entry : fs::directory_iterator(folder)) out.push_back(entry.path().filename());
  std::sort(out.begin(), out.end());
  return out;
}

void writeText(OutputFile& file, const std::string& text) {
  file.write(text.data(), text.size());
}

TEST(OutputFile, AFailedRenameGivesItsReason) {
  // The target turned into a folder after the checks: the rename fails with the system's
  // reason (EISDIR), not with that of the clean-up that follows it.
  TempDir dir;
  fs::create_directories(dir.file("c.png"));
  try {
    writeImageAtomically(dir.file("c.png"), cv::Mat(2, 2, CV_8UC3));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              dir.file("c.png") + ": cannot replace file: " +
                  std::error_code(EISDIR, std::generic_category()).message());
  }
  EXPECT_EQ(names(dir.path), std::vector<std::string>{"c.png"});
}

TEST(OutputFile, AReplacedFileLeavesTheNewOneAloneUnderItsName) {
  // Over an old file (exchanged, then the old one removed), and where there is none (renamed).
  TempDir dir;
  dir.write("out.png", "old");
  OutputFile over(dir.file("out.png"));
  writeText(over, "new");
  EXPECT_EQ(test::readFile(dir.file("out.png")), "old");  // until the commit
  over.commit();
  EXPECT_EQ(test::readFile(dir.file("out.png")), "new");
  EXPECT_EQ(names(dir.path), std::vector<std::string>{"out.png"});

  OutputFile fresh(dir.file("fresh.png"));
  writeText(fresh, "first");
  fresh.commit();
  EXPECT_EQ(test::readFile(dir.file("fresh.png")), "first");
  EXPECT_EQ(names(dir.path), (std::vector<std::string>{"fresh.png", "out.png"}));
}

TEST(OutputFile, ASymbolicLinkAtTheTargetIsReplacedNotItsTarget) {
  TempDir dir;
  dir.write("target.png", "target");
  fs::create_symlink(dir.file("target.png"), dir.file("link.png"));
  OutputFile file(dir.file("link.png"));
  writeText(file, "new");
  file.commit();
  EXPECT_FALSE(fs::is_symlink(dir.file("link.png")));
  EXPECT_EQ(test::readFile(dir.file("link.png")), "new");
  EXPECT_EQ(test::readFile(dir.file("target.png")), "target");
  EXPECT_EQ(names(dir.path), (std::vector<std::string>{"link.png", "target.png"}));
}

TEST(OutputFile, WritesInAPrivateFolderOfAnUnguessableName) {
  TempDir dir;
  OutputFile a(dir.file("out.png")), b(dir.file("out.png"));
  writeText(a, "a");
  const std::vector<std::string> folders = names(dir.path);
  ASSERT_EQ(folders.size(), 2u);  // one each, and nothing else: no file beside the target
  EXPECT_NE(folders[0], folders[1]);
  for (const std::string& name : folders) {
    SCOPED_TRACE(name);
    ASSERT_EQ(name.size(), std::string(".zrender-").size() + 16);
    EXPECT_EQ(name.rfind(".zrender-", 0), 0u);
    for (char c : name.substr(9)) EXPECT_TRUE(c >= 'a' && c <= 'z');
    struct stat status {};
    ASSERT_EQ(::lstat(dir.file(name).c_str(), &status), 0);
    EXPECT_TRUE(S_ISDIR(status.st_mode));
    EXPECT_EQ(status.st_mode & 0777, 0700u);  // no one else may enter it or plant a file
    EXPECT_EQ(status.st_uid, ::geteuid());
  }
}

TEST(OutputFile, NeverWritesThroughALinkInItsPlace) {
  // Nobody else can enter the private folder; should a link stand where the file goes anyway,
  // creating the file fails (O_EXCL | O_NOFOLLOW) and the link's target is untouched.
  TempDir dir;
  dir.write("victim", "precious");
  OutputFile file(dir.file("out.png"));
  std::string folder;
  for (const std::string& name : names(dir.path))
    if (name.rfind(".zrender-", 0) == 0) folder = dir.file(name);
  ASSERT_FALSE(folder.empty());
  fs::create_symlink(dir.file("victim"), folder + "/out.png");
  EXPECT_THROW(writeText(file, "overwritten?"), InputError);
  EXPECT_EQ(test::readFile(dir.file("victim")), "precious");
}

TEST(OutputFile, AnUncommittedFileLeavesNothing) {
  TempDir dir;
  dir.write("out.png", "old");
  {
    OutputFile file(dir.file("out.png"));
    writeText(file, "half");
  }
  EXPECT_EQ(test::readFile(dir.file("out.png")), "old");
  EXPECT_EQ(names(dir.path), std::vector<std::string>{"out.png"});
  checkWritable(dir.file("deeper/new.png"));  // makes the folder, leaves no probe
  EXPECT_TRUE(fs::is_empty(dir.file("deeper")));
}

TEST(OutputFile, ANameAsLongAsTheSystemAllowsWorks) {
  TempDir dir;
  const std::string name = std::string(size_t(NAME_MAX) - 4, 'n') + ".png";
  checkWritable(dir.file(name));
  writeFileAtomically(dir.file(name), "long");
  EXPECT_EQ(test::readFile(dir.file(name)), "long");
  EXPECT_EQ(names(dir.path), std::vector<std::string>{name});
}

TEST(OutputFile, TwoSpellingsOfOneFileAreOneOutput) {
  TempDir dir;
  fs::create_directories(dir.file("sub"));
  fs::create_directory_symlink(dir.file("sub"), dir.file("alias"));
  const auto clash = [&](const std::string& a, const std::string& b) {
    try {
      checkDistinctOutputs({{"-o", a}, {"--ids", b}});
      return std::string();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
  };
  EXPECT_EQ(clash(dir.file("x.png"), dir.file("x.png")),
            "command line: -o and --ids both name " + dir.file("x.png"));
  EXPECT_NE(clash(dir.file("x.png"), dir.path + "/./x.png"), "");
  EXPECT_NE(clash(dir.file("sub/x.png"), dir.file("sub/../sub/x.png")), "");
  EXPECT_NE(clash(dir.file("sub/x.png"), dir.file("alias/x.png")), "");
  EXPECT_EQ(clash(dir.file("x.png"), dir.file("y.png")), "");
  EXPECT_EQ(clash(dir.file("sub/x.png"), dir.file("x.png")), "");
}

}  // namespace
}  // namespace zrender
