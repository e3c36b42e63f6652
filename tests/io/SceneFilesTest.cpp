// loadScene (io/SceneFiles): with threads, a `texture` key's image is decoded while the model
// loads; the scene, the error and the warnings are those of one thread.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "support/TestSupport.hpp"
#include "zrender/base/Error.hpp"
#include "zrender/base/Threads.hpp"
#include "zrender/io/SceneFiles.hpp"

namespace zrender {
namespace {

TEST(SceneFiles, ATexturedSceneLoadsTheSameOnTwoThreads) {
  const SceneSettings settings = test::projectScene("spot");
  if (!std::filesystem::exists(settings.modelPath)) GTEST_SKIP() << "spot not present";
  ASSERT_TRUE(settings.texture.has_value());
  const Threads two(2);
  Warnings alone, together;
  const Scene a = loadScene(settings, alone), b = loadScene(settings, together, &two);
  EXPECT_EQ(a.mesh->positions, b.mesh->positions);
  EXPECT_EQ(a.mesh->faceStart, b.mesh->faceStart);
  ASSERT_FALSE(a.texture.empty());
  EXPECT_TRUE(samePixels(a.texture, b.texture));
  EXPECT_EQ(alone, together);
}

// Both the model and the texture are missing: the model's error, as when loaded in order.
TEST(SceneFiles, TheModelsErrorComesFirstOnTwoThreads) {
  SceneSettings settings = test::projectScene("spot");
  settings.modelPath = "/nonexistent/model.obj";
  settings.texture = std::filesystem::path("/nonexistent/texture.png");
  const Threads one(1), two(2);
  for (const Threads* threads : {&one, &two}) {
    Warnings warnings;
    try {
      loadScene(settings, warnings, threads);
      FAIL() << "no error";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), "/nonexistent/model.obj: cannot open file");
    }
  }
}

}  // namespace
}  // namespace zrender
