// Hostile material files and textures end to end (docs/design.md, Errors): what a model's
// material file names may be missing or not an image (a warning, the model still renders); the
// settings' own "texture" key may not (an error naming the key).

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "support/HostileRuns.hpp"

namespace zrender {
namespace {

namespace fs = std::filesystem;
using namespace test;

TEST(HostileMaterials, MissingMaterialFileOrTextureIsAWarning) {
  TempDir dir;
  // A missing .mtl: warning, exit 0, the model still renders.
  dir.write("m.obj", std::string("mtllib nope.mtl\nusemtl red\n") + kSquareObj);
  Outcome r = renderModel(dir, "zbuffer");
  EXPECT_GT(coveredPixels(expectPicture(r, dir.file("out.png"), kImageSize, kImageSize)), 0);
  EXPECT_NE(r.err.find("zrender: warning: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("nope.mtl"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("error"), std::string::npos) << r.err;

  // A material whose map_Kd is missing: warning, exit 0, even with texture shading.
  dir.write("m.mtl", "newmtl red\nKd 1 0 0\nmap_Kd missing.png\n");
  dir.write("m.obj", std::string("mtllib m.mtl\nvt 0 0\nvt 1 0\nvt 1 1\nusemtl red\n") +
                         "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nf 1/1 2/2 3/3\n");
  r = renderModel(dir, "zbuffer", {"--shading", "texture"});
  EXPECT_GT(coveredPixels(expectPicture(r, dir.file("out.png"), kImageSize, kImageSize)), 0);
  EXPECT_EQ(r.err.rfind("zrender: warning: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("missing.png"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 2) << r.err;  // and the summary
}

TEST(HostileMaterials, MissingTextureOfTheSettingsIsAnError) {
  // The scene's own "texture" key is a value the user chose (docs/design.md, Settings and Errors):
  // a file that is not there, or a folder, is an error naming it and the key, and nothing is
  // written. Only zrender's line: none from OpenCV, which would print one for a file it cannot
  // open.
  TempDir dir;
  dir.write("m.obj", "vt 0 0\nvt 1 0\nvt 1 1\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nf 1/1 2/2 3/3\n");
  fs::create_directories(dir.file("folder.png"));
  for (const std::string name : {"nope.png", "folder.png"}) {
    SCOPED_TRACE(name);
    writeScene(dir, R"("eye": [0, 0, 3], "shading": "texture", "texture": ")" + name + "\"");
    expectQuickCleanError(renderScene(dir, "zbuffer"),
                          {name + ": texture cannot be opened", "key 'texture' of scene 's'"});
    EXPECT_FALSE(fs::exists(dir.file("out.png")));
  }
}

// A PNG signature and header claiming `width` x `height`, then nothing: a truncated image.
std::string truncatedPng(uint32_t width, uint32_t height) {
  std::string s = "\x89PNG\r\n\x1a\n";
  s += std::string("\0\0\0\x0dIHDR", 8);
  for (uint32_t v : {width, height})
    for (int shift = 24; shift >= 0; shift -= 8) s += char((v >> shift) & 0xFF);
  s += std::string("\x08\x02\0\0\0", 5);  // 8-bit RGB
  s += std::string("\0\0\0\0", 4);        // CRC (wrong on purpose)
  return s;
}

TEST(HostileMaterials, MaterialTextureThatIsNotAnImageIsAWarning) {
  const std::vector<std::pair<std::string, std::string>> textures = {
      {"text", "this is not an image\n"},
      {"empty", ""},
      {"truncated png", truncatedPng(64, 64)},
      {"png claiming 1000000 x 1000000 pixels", truncatedPng(1000000, 1000000)},
  };
  for (const auto& [name, bytes] : textures) {
    SCOPED_TRACE(name);
    TempDir dir;
    dir.write("tex.png", bytes);
    dir.write("m.mtl", "newmtl t\nmap_Kd tex.png\n");
    dir.write("m.obj",
              "mtllib m.mtl\nusemtl t\nvt 0 0\nvt 1 0\nvt 1 1\n"
              "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nf 1/1 2/2 3/3\n");
    const Outcome r = renderModel(dir, "zbuffer", {"--shading", "texture"});
    EXPECT_GT(coveredPixels(expectPicture(r, dir.file("out.png"), kImageSize, kImageSize)), 0);
    EXPECT_NE(r.err.find("zrender: warning: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("tex.png"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 2) << r.err;  // and the summary
    // The same file named by the settings' "texture" key, a value the user chose: an error.
    writeScene(dir, R"("eye": [0, 0, 3], "texture": "tex.png", "shading": "texture")");
    fs::remove(dir.file("out.png"));
    expectQuickCleanError(
        renderScene(dir, "zbuffer"),
        {"tex.png: texture cannot be read as an image", "key 'texture' of scene 's'"});
    EXPECT_FALSE(fs::exists(dir.file("out.png")));
  }
}

}  // namespace
}  // namespace zrender
