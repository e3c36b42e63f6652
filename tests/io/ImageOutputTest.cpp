// Writing an image (writeImageAtomically): a rename that fails gives its own reason; a file
// replaced (replaceFile) over an old one, where there was none, and through a symbolic link.

#include <gtest/gtest.h>

#include <cerrno>
#include <filesystem>
#include <iterator>
#include <string>
#include <system_error>

#include <opencv2/core.hpp>

#include "support/TestSupport.hpp"
#include "zrender/base/Error.hpp"
#include "zrender/io/ImageOutput.hpp"

namespace zrender {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

TEST(ImageOutput, AFailedRenameGivesItsReason) {
  // The target turned into a folder after the checks: the rename fails with the system's
  // reason (EISDIR), not with that of the clean-up that follows it.
  TempDir dir;
  fs::create_directories(dir.file("c.png"));
  try {
    writeImageAtomically(dir.file("c.png"), Image(2, 2, PixelFormat::kBgr8));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              dir.file("c.png") + ": cannot replace file: " +
                  std::error_code(EISDIR, std::generic_category()).message());
  }
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator()), 1);
}

size_t entries(const fs::path& folder) {
  return size_t(std::distance(fs::directory_iterator(folder), fs::directory_iterator()));
}

TEST(ImageOutput, AReplacedFileLeavesTheNewOneAloneUnderItsName) {
  // Over an old file (exchanged, then the old one removed), and where there is none (renamed).
  TempDir dir;
  dir.write("out.png", "old");
  dir.write(".tmp", "new");
  std::error_code ec;
  replaceFile(dir.file(".tmp"), dir.file("out.png"), ec);
  EXPECT_FALSE(ec) << ec.message();
  EXPECT_EQ(test::readFile(dir.file("out.png")), "new");
  EXPECT_EQ(entries(dir.path), 1u);

  dir.write(".tmp2", "first");
  replaceFile(dir.file(".tmp2"), dir.file("fresh.png"), ec);
  EXPECT_FALSE(ec) << ec.message();
  EXPECT_EQ(test::readFile(dir.file("fresh.png")), "first");
  EXPECT_EQ(entries(dir.path), 2u);
}

TEST(ImageOutput, AReplacedSymbolicLinkIsReplacedNotItsTarget) {
  // As a rename does: the link's name now holds the new file, and the file it pointed to is
  // untouched.
  TempDir dir;
  dir.write("target.png", "target");
  fs::create_symlink(dir.file("target.png"), dir.file("link.png"));
  dir.write(".tmp", "new");
  std::error_code ec;
  replaceFile(dir.file(".tmp"), dir.file("link.png"), ec);
  EXPECT_FALSE(ec) << ec.message();
  EXPECT_FALSE(fs::is_symlink(dir.file("link.png")));
  EXPECT_EQ(test::readFile(dir.file("link.png")), "new");
  EXPECT_EQ(test::readFile(dir.file("target.png")), "target");
  EXPECT_EQ(entries(dir.path), 2u);
}

}  // namespace
}  // namespace zrender
