#include "zrender/base/Plugin.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>

namespace zrender {
namespace {

namespace fs = std::filesystem;

// The message of pluginObject's error for `fileName`, or "no error".
std::string loadError(const std::string& fileName) {
  try {
    pluginObject(fileName, "zrenderForeignPlugin");
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "no error";
}

// The folder of this test program, where tests/CMakeLists.txt puts the foreign plugins.
std::string testFolder() {
  return fs::read_symlink("/proc/self/exe").parent_path().string();
}

TEST(Plugin, AThisBuildsPluginLoads) {
  EXPECT_NE(pluginObject("libzrender_codecs.so", "zrenderCodecPlugin"), nullptr);
}

TEST(Plugin, APluginOfAnotherBuildIsRefusedByName) {
  const std::string message = loadError("libzrender_foreign.so");
  const std::string start = "cannot load libzrender_foreign.so: " + testFolder() +
                            "/libzrender_foreign.so is from another build of zrender (interface "
                            "0000000000000000, this zrender's ";
  EXPECT_EQ(message.rfind(start, 0), 0u) << message;
  const std::string end = "); install zrender again";
  ASSERT_GE(message.size(), start.size() + 16 + end.size()) << message;
  EXPECT_EQ(message.substr(message.size() - end.size()), end) << message;
}

TEST(Plugin, APluginWithoutATagIsRefusedByName) {
  const std::string message = loadError("libzrender_untagged.so");
  EXPECT_EQ(message.rfind("cannot load libzrender_untagged.so: " + testFolder() +
                              "/libzrender_untagged.so is from another build of zrender "
                              "(interface none, this zrender's ",
                          0),
            0u)
      << message;
}

TEST(Plugin, AMissingPluginSaysWhereItWasLookedFor) {
  const fs::path folder = testFolder();
  EXPECT_EQ(loadError("libzrender_nowhere.so"),
            "cannot load libzrender_nowhere.so: not found in " +
                (folder.parent_path() / "lib" / "zrender").string() + " nor beside " +
                (folder / "zrender_tests").string());
}

}  // namespace
}  // namespace zrender
