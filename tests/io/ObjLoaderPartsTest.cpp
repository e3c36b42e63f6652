// The OBJ loader on several threads (docs/design.md, Threads): tinyobjloader parses the text in
// parts cut at line ends, joined as one pass would give them; relative indices, the ordinal of
// a non-finite coordinate and material statements cross the cuts.

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "support/ObjLoaderFixture.hpp"
#include "support/TestSupport.hpp"
#include "zrender/base/Threads.hpp"
#include "zrender/io/ObjLoader.hpp"
#include "zrender/scene/Mesh.hpp"

namespace zrender {
namespace {

using ObjLoaderParts = test::ObjLoaderFixture;
using test::expectMessage;
using Ints = std::vector<int32_t>;
namespace fs = std::filesystem;

// Every line a part of its own (parts of at least one byte).
constexpr size_t kLinePerPart = 1;

Ints fieldOf(const Mesh& mesh, int32_t Corner::*field) {
  Ints values;
  for (const Corner& c : mesh.corners) values.push_back(c.*field);
  return values;
}

// The mesh of these bytes loaded on one thread, and on two with parts of `minPartBytes`.
std::vector<Mesh> loadBothWays(const std::string& bytes, const fs::path& path,
                               size_t minPartBytes) {
  const Threads two(2);
  std::vector<Mesh> meshes;
  for (const Threads* threads : {static_cast<const Threads*>(nullptr), &two}) {
    Warnings warnings;
    meshes.push_back(loadObjFromText(bytes, path, warnings, threads, minPartBytes));
    EXPECT_TRUE(warnings.empty());
  }
  return meshes;
}

TEST_F(ObjLoaderParts, RelativeIndicesCountFromThePartsBefore) {
  const std::string bytes =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
      "vt 0 0\nvt 1 0\nvn 0 0 1\n"
      "f -4/-2/-1 -3/-1/-1 -2/-1/-1\n"
      "v 2 0 0\nv 2 1 0\nvt 0.5 0.5\n"
      "f -1/-1 -2/-2 -5/-3\n"
      "f 1 5 6\n";
  for (const Mesh& mesh : loadBothWays(bytes, dir_ / "m.obj", kLinePerPart)) {
    ASSERT_EQ(mesh.faceCount(), 3u);
    EXPECT_EQ(mesh.faceStart, (std::vector<uint32_t>{0, 3, 6, 9}));
    EXPECT_EQ(fieldOf(mesh, &Corner::position), (Ints{0, 1, 2, 5, 4, 1, 0, 4, 5}));
    EXPECT_EQ(fieldOf(mesh, &Corner::texcoord), (Ints{0, 1, 1, 2, 1, 0, -1, -1, -1}));
    EXPECT_EQ(fieldOf(mesh, &Corner::normal), (Ints{0, 0, 0, -1, -1, -1, -1, -1, -1}));
    EXPECT_EQ(mesh.positions.size(), 6u);
    EXPECT_DOUBLE_EQ(mesh.positions[5][1], 1.0);
    EXPECT_DOUBLE_EQ(mesh.texcoords[2][0], 0.5);
  }
}

TEST_F(ObjLoaderParts, ANonFiniteCoordinateInALaterPartNamesItsLine) {
  const std::string bytes = "v 0 0 0\nv 1 0 0\n# two lines on\n\nvt 0 0\nv 1 1e400 0\nf 1 2 3\n";
  const Threads two(2);
  for (const Threads* threads : {static_cast<const Threads*>(nullptr), &two}) {
    Warnings warnings;
    try {
      loadObjFromText(bytes, dir_ / "m.obj", warnings, threads, kLinePerPart);
      FAIL() << "no error";
    } catch (const InputError& e) {
      expectMessage(e.what(), dir_ / "m.obj", {":6: ", "NaN or infinite"});
    }
  }
}

TEST_F(ObjLoaderParts, MaterialStatementsCarryAcrossTheCuts) {
  write("m.mtl", "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n");
  const std::string bytes =
      "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
      "f 1 2 3\nusemtl red\nf 1 3 4\nusemtl blue\nf 2 3 4\nf 1 2 4\n";
  // Cut at every line, and in one part (a small text).
  for (const size_t minPartBytes : {kLinePerPart, kObjMinPartBytes}) {
    for (const Mesh& mesh : loadBothWays(bytes, dir_ / "m.obj", minPartBytes)) {
      EXPECT_EQ(mesh.faceMaterial, (Ints{-1, 0, 1, 1}));
      ASSERT_EQ(mesh.materials.size(), 2u);
      EXPECT_EQ(mesh.materials[1].name, "blue");
    }
  }
}

TEST_F(ObjLoaderParts, StanfordBunnyInPartsOfTheDefaultSize) {
  const fs::path path = ZRENDER_SOURCE_DIR "/models/bunny/bunny.obj";
  if (!fs::exists(path)) GTEST_SKIP() << path << " not present";
  const std::string bytes = test::readFile(path.string());
  ASSERT_GT(bytes.size(), 4 * kObjMinPartBytes);  // so at least 4 parts
  const std::vector<Mesh> meshes = loadBothWays(bytes, path, kObjMinPartBytes);
  const Mesh &alone = meshes[0], &parts = meshes[1];
  EXPECT_EQ(parts.faceCount(), 69451u);
  EXPECT_EQ(parts.positions, alone.positions);
  EXPECT_EQ(parts.faceStart, alone.faceStart);
  EXPECT_EQ(fieldOf(parts, &Corner::position), fieldOf(alone, &Corner::position));
  EXPECT_EQ(parts.faceMaterial, alone.faceMaterial);
}

}  // namespace
}  // namespace zrender
