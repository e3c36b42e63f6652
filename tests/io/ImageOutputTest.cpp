// Writing an image (writeImageAtomically): a rename that fails gives its own reason.

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
    writeImageAtomically(dir.file("c.png"), cv::Mat(2, 2, CV_8UC3, cv::Scalar(1, 2, 3)));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              dir.file("c.png") + ": cannot replace file: " +
                  std::error_code(EISDIR, std::generic_category()).message());
  }
  EXPECT_EQ(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator()), 1);
}

}  // namespace
}  // namespace zrender
