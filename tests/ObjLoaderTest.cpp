#include <atomic>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "zrender/base/Error.hpp"
#include "zrender/io/ObjLoader.hpp"
#include "zrender/scene/Mesh.hpp"

namespace zrender {
namespace {

namespace fs = std::filesystem;

// Each test gets its own folder under the system temp folder, removed afterwards.
class ObjLoaderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    static std::atomic<int> counter{0};
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() / ("zrender_objloader_" + std::to_string(::getpid()) + "_" +
                                        std::to_string(counter++) + "_" + info->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }

  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  // Writes bytes exactly as given (binary: no newline translation).
  fs::path write(const std::string& name, const std::string& bytes) {
    const fs::path path = dir_ / name;
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    EXPECT_TRUE(out.good()) << path;
    return path;
  }

  Mesh load(const std::string& name, const std::string& bytes) {
    Warnings warnings;
    Mesh mesh = loadObj(write(name, bytes), warnings);
    EXPECT_TRUE(warnings.empty()) << (warnings.empty() ? "" : warnings.front());
    return mesh;
  }

  // The InputError message of loading these bytes, or "no error".
  std::string loadError(const std::string& bytes, const std::string& name = "m.obj") {
    const fs::path path = write(name, bytes);
    Warnings warnings;
    try {
      loadObj(path, warnings);
    } catch (const InputError& e) {
      return e.what();
    }
    return "no error";
  }

  fs::path dir_;
};

// Message check: starts with the file path, holds each expected piece.
void expectMessage(const std::string& message, const fs::path& file,
                   std::initializer_list<const char*> pieces) {
  EXPECT_EQ(message.rfind(file.string(), 0), 0u) << message;
  for (const char* piece : pieces) {
    EXPECT_NE(message.find(piece), std::string::npos) << "'" << piece << "' not in: " << message;
  }
}

std::vector<int32_t> positionsOf(const Mesh& mesh) {
  std::vector<int32_t> out;
  for (const Corner& c : mesh.corners) out.push_back(c.position);
  return out;
}

std::vector<int32_t> texcoordsOf(const Mesh& mesh) {
  std::vector<int32_t> out;
  for (const Corner& c : mesh.corners) out.push_back(c.texcoord);
  return out;
}

std::vector<int32_t> normalsOf(const Mesh& mesh) {
  std::vector<int32_t> out;
  for (const Corner& c : mesh.corners) out.push_back(c.normal);
  return out;
}

using Ints = std::vector<int32_t>;
using Offsets = std::vector<uint32_t>;

const char kSquare[] =
    "v 0 0 0\n"
    "v 1 0 0\n"
    "v 1 1 0\n"
    "v 0 1 0\n";

TEST_F(ObjLoaderTest, Triangle) {
  const Mesh mesh = load("t.obj",
                         "# a triangle\n"
                         "v 0.5 -2.25 3\n"
                         "v 1 0 0\n"
                         "v 0 1e1 -1.25E-1\n"
                         "f 1 2 3\n");
  ASSERT_EQ(mesh.faceCount(), 1u);
  EXPECT_EQ(mesh.faceStart, (Offsets{0, 3}));
  EXPECT_EQ(positionsOf(mesh), (Ints{0, 1, 2}));
  EXPECT_EQ(texcoordsOf(mesh), (Ints{-1, -1, -1}));
  EXPECT_EQ(normalsOf(mesh), (Ints{-1, -1, -1}));
  EXPECT_EQ(mesh.faceMaterial, (Ints{-1}));
  ASSERT_EQ(mesh.positions.size(), 3u);
  EXPECT_DOUBLE_EQ(mesh.positions[0][0], 0.5);
  EXPECT_DOUBLE_EQ(mesh.positions[0][1], -2.25);
  EXPECT_DOUBLE_EQ(mesh.positions[0][2], 3.0);
  EXPECT_DOUBLE_EQ(mesh.positions[2][1], 10.0);
  EXPECT_DOUBLE_EQ(mesh.positions[2][2], -0.125);
  EXPECT_FALSE(mesh.hasNormals());
  EXPECT_FALSE(mesh.hasTexcoords());
  EXPECT_TRUE(mesh.materials.empty());
}

TEST_F(ObjLoaderTest, TriangleThenQuad) {
  const Mesh mesh = load("q.obj", std::string(kSquare) +
                                      "v 2 0 0\n"
                                      "f 1 2 3\n"
                                      "f 5 3 4 1\n");
  ASSERT_EQ(mesh.faceCount(), 2u);
  EXPECT_EQ(mesh.faceStart, (Offsets{0, 3, 7}));
  EXPECT_EQ(mesh.cornerCount(1), 4u);
  EXPECT_EQ(positionsOf(mesh), (Ints{0, 1, 2, 4, 2, 3, 0}));
  EXPECT_EQ(mesh.faceCorners(1)[0].position, 4);
  EXPECT_EQ(mesh.faceMaterial, (Ints{-1, -1}));
}

TEST_F(ObjLoaderTest, NegativeIndicesCountBackFromTheLineBefore) {
  // The first face sees 4 vertices (-4 -> 0); the second sees 5 (-1 -> 4, -5 -> 0).
  const Mesh mesh = load("n.obj", std::string(kSquare) +
                                      "f -4 -3 -2 -1\n"
                                      "v 2 2 0\n"
                                      "f -1 -5 -2\n");
  ASSERT_EQ(mesh.faceCount(), 2u);
  EXPECT_EQ(positionsOf(mesh), (Ints{0, 1, 2, 3, 4, 0, 3}));
}

TEST_F(ObjLoaderTest, TexcoordAndNormalIndices) {
  const Mesh mesh = load("tn.obj", std::string(kSquare) +
                                       "vt 0 0\n"
                                       "vt 1 0\n"
                                       "vt 0.25 0.75 0\n"
                                       "vn 0 0 1\n"
                                       "vn 0 0 -1\n"
                                       "f 1/1/2 2/2/2 3/3/2\n"
                                       "f 1//1 3//1 4//1\n"
                                       "f 1/3 2/2 4/1\n"
                                       "f 2/-1/-2 3/-3/-1 4/1/1\n");
  ASSERT_EQ(mesh.faceCount(), 4u);
  EXPECT_EQ(positionsOf(mesh), (Ints{0, 1, 2, 0, 2, 3, 0, 1, 3, 1, 2, 3}));
  EXPECT_EQ(texcoordsOf(mesh), (Ints{0, 1, 2, -1, -1, -1, 2, 1, 0, 2, 0, 0}));
  EXPECT_EQ(normalsOf(mesh), (Ints{1, 1, 1, 0, 0, 0, -1, -1, -1, 0, 1, 0}));
  ASSERT_EQ(mesh.texcoords.size(), 3u);
  EXPECT_DOUBLE_EQ(mesh.texcoords[2][0], 0.25);
  EXPECT_DOUBLE_EQ(mesh.texcoords[2][1], 0.75);
  ASSERT_EQ(mesh.normals.size(), 2u);
  EXPECT_DOUBLE_EQ(mesh.normals[1][2], -1.0);
}

TEST_F(ObjLoaderTest, ConcaveHexagonStaysOneFace) {
  // An L shape: six corners, concave at (1, 1).
  const Mesh mesh = load("l.obj",
                         "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\n"
                         "f 1 2 3 4 5 6\n");
  ASSERT_EQ(mesh.faceCount(), 1u);
  EXPECT_EQ(mesh.faceStart, (Offsets{0, 6}));
  EXPECT_EQ(positionsOf(mesh), (Ints{0, 1, 2, 3, 4, 5}));
}

TEST_F(ObjLoaderTest, DegenerateFacesKeepTheirIds) {
  // tinyobjloader's shapes would drop the 1- and 2-corner faces and renumber the triangle.
  const Mesh mesh = load("d.obj", std::string(kSquare) +
                                      "f 1\n"
                                      "f 1 2\n"
                                      "f 2 3 4\n");
  ASSERT_EQ(mesh.faceCount(), 3u);
  EXPECT_EQ(mesh.faceStart, (Offsets{0, 1, 3, 6}));
  EXPECT_EQ(positionsOf(mesh), (Ints{0, 0, 1, 1, 2, 3}));
}

TEST_F(ObjLoaderTest, LargeFacesKeepAllCorners) {
  // 300 corners would wrap to 44 in tinyobjloader's unsigned char corner count.
  std::string obj;
  for (int i = 0; i < 300; ++i) obj += "v " + std::to_string(i) + " 0 0\n";
  obj += "f";
  for (int i = 1; i <= 300; ++i) obj += " " + std::to_string(i);
  obj += "\nf";
  for (uint32_t i = 0; i < kMaxFaceCorners; ++i) obj += " " + std::to_string(i % 300 + 1);
  obj += "\n";
  const Mesh mesh = load("big.obj", obj);
  ASSERT_EQ(mesh.faceCount(), 2u);
  EXPECT_EQ(mesh.cornerCount(0), 300u);
  EXPECT_EQ(mesh.cornerCount(1), kMaxFaceCorners);
  EXPECT_EQ(mesh.faceCorners(0)[299].position, 299);
  EXPECT_EQ(mesh.faceCorners(1)[300].position, 0);
}

TEST_F(ObjLoaderTest, FacesStayInFileOrderAcrossGroupsObjectsAndMaterials) {
  write("m.mtl", "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n");
  const Mesh mesh = load("order.obj", std::string("mtllib m.mtl\n") + kSquare +
                                          "g a\n"
                                          "f 1 2 3\n"
                                          "o b\n"
                                          "usemtl blue\n"
                                          "f 2 3 4\n"
                                          "g c\n"
                                          "usemtl red\n"
                                          "f 3 4 1\n"
                                          "g a\n"
                                          "usemtl blue\n"
                                          "s 1\n"
                                          "l 1 2\n"
                                          "p 3\n"
                                          "f 4 1 2\n");
  ASSERT_EQ(mesh.faceCount(), 4u);
  EXPECT_EQ(positionsOf(mesh), (Ints{0, 1, 2, 1, 2, 3, 2, 3, 0, 3, 0, 1}));
  EXPECT_EQ(mesh.faceMaterial, (Ints{-1, 1, 0, 1}));
}

TEST_F(ObjLoaderTest, MaterialWithTexture) {
  write("tex.png", "not really a png; only its existence matters here");
  write("m.mtl",
        "# materials\n"
        "newmtl plain\n"
        "Kd 0.5 0.25 1\n"
        "newmtl textured\n"
        "Kd 1 1 1\n"
        "map_Kd tex.png\n");
  const Mesh mesh = load("m.obj", std::string("mtllib m.mtl\n") + kSquare +
                                      "f 1 2 3\n"
                                      "usemtl textured\n"
                                      "f 1 3 4\n"
                                      "usemtl plain\n"
                                      "f 2 3 4\n");
  ASSERT_EQ(mesh.materials.size(), 2u);
  EXPECT_EQ(mesh.materials[0].name, "plain");
  EXPECT_FLOAT_EQ(mesh.materials[0].diffuse[0], 0.5f);
  EXPECT_FLOAT_EQ(mesh.materials[0].diffuse[1], 0.25f);
  EXPECT_FLOAT_EQ(mesh.materials[0].diffuse[2], 1.0f);
  EXPECT_EQ(mesh.materials[0].diffuseTexture, "");
  EXPECT_EQ(mesh.materials[1].name, "textured");
  EXPECT_EQ(mesh.materials[1].diffuseTexture, (dir_ / "tex.png").string());
  EXPECT_EQ(mesh.faceMaterial, (Ints{-1, 1, 0}));
}

// Exporters on Windows write map_Kd with backslashes; the file is found with slashes.
TEST_F(ObjLoaderTest, TexturePathWithBackslashes) {
  fs::create_directories(dir_ / "maps");
  write("maps/wood.png", "only its existence matters here");
  write("m.mtl", "newmtl wood\nmap_Kd maps\\wood.png\n");
  Warnings warnings;
  const Mesh mesh = loadObj(
      write("m.obj", std::string("mtllib m.mtl\nusemtl wood\n") + kSquare + "f 1 2 3\n"), warnings);
  ASSERT_EQ(mesh.materials.size(), 1u);
  EXPECT_EQ(mesh.materials[0].diffuseTexture, (dir_ / "maps/wood.png").string());
  EXPECT_TRUE(warnings.empty());
}

TEST_F(ObjLoaderTest, MissingMtlIsAWarning) {
  Warnings warnings;
  const Mesh mesh =
      loadObj(write("m.obj", std::string("mtllib gone.mtl\nusemtl red\n") + kSquare + "f 1 2 3\n"),
              warnings);
  EXPECT_EQ(mesh.faceCount(), 1u);
  EXPECT_EQ(mesh.faceMaterial, (Ints{-1}));
  EXPECT_TRUE(mesh.materials.empty());
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], (dir_ / "m.obj").string() + ": material file 'gone.mtl' not found");
}

TEST_F(ObjLoaderTest, MissingTextureIsAWarning) {
  write("m.mtl", "newmtl skin\nKd 1 0.5 0\nmap_Kd missing.png\n");
  Warnings warnings;
  const Mesh mesh = loadObj(
      write("m.obj", std::string("mtllib m.mtl\nusemtl skin\n") + kSquare + "f 1 2 3\n"), warnings);
  ASSERT_EQ(mesh.materials.size(), 1u);
  EXPECT_EQ(mesh.materials[0].diffuseTexture, "");
  EXPECT_FLOAT_EQ(mesh.materials[0].diffuse[1], 0.5f);
  EXPECT_EQ(mesh.faceMaterial, (Ints{0}));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], (dir_ / "m.obj").string() + ": texture 'missing.png' not found");
}

TEST_F(ObjLoaderTest, UnknownMaterialNameIsAWarning) {
  write("m.mtl", "newmtl red\nKd 1 0 0\n");
  Warnings warnings;
  const Mesh mesh =
      loadObj(write("m.obj", std::string("mtllib m.mtl\nusemtl green\n") + kSquare + "f 1 2 3\n"),
              warnings);
  EXPECT_EQ(mesh.faceMaterial, (Ints{-1}));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], (dir_ / "m.obj").string() + ": material 'green' not found");
}

TEST_F(ObjLoaderTest, CrlfTabsBomAndNoFinalNewline) {
  const Mesh mesh = load("w.obj",
                         "\xEF\xBB\xBFv 0 0 0\r\n"
                         "v\t1\t0\t0\r\n"
                         "  \tv 1 1 0 \r\n"
                         "\r\n"
                         "v 0 1 0\r"  // a lone CR ends a line too
                         "f\t1 2\t3  4\t");
  ASSERT_EQ(mesh.positions.size(), 4u);
  EXPECT_DOUBLE_EQ(mesh.positions[1][0], 1.0);
  ASSERT_EQ(mesh.faceCount(), 1u);
  EXPECT_EQ(positionsOf(mesh), (Ints{0, 1, 2, 3}));
}

TEST_F(ObjLoaderTest, LineNumbersCountCrlfAndLoneCr) {
  // Lines: 1 v, 2 v, 3 blank, 4 v, 5 bad.
  const fs::path path = dir_ / "m.obj";
  expectMessage(loadError("v 0 0 0\r\nv 1 0 0\r\r\nv 0 1 0\rv 1 x 0\r\nf 1 2 3\r\n"), path,
                {":5: ", "'x'"});
}

TEST_F(ObjLoaderTest, NonUtf8CommentsAndGroupNames) {
  const Mesh mesh = load("c.obj", std::string("# \xFF\xFE caf\xE9\n") + kSquare +
                                      "g \xFF\xFE\x01\n"
                                      "f 1 2 3\n"
                                      "\x7F\x80 unknown statement\n");
  EXPECT_EQ(mesh.faceCount(), 1u);
}

TEST_F(ObjLoaderTest, MultiMegabyteLines) {
  const std::string longComment = "# " + std::string(4u << 20, 'x') + "\n";
  const Mesh mesh =
      load("long.obj", longComment + kSquare + "o " + std::string(3u << 20, 'y') + "\nf 1 2 3\n");
  EXPECT_EQ(mesh.faceCount(), 1u);
  // A multi-megabyte face line is refused for its corner count, with its line number.
  std::string face = "f";
  for (int i = 0; i < 500000; ++i) face += " 1 2 3 4";
  expectMessage(loadError(std::string(kSquare) + face + "\n"), dir_ / "m.obj",
                {":5: ", "more than 4096 corners"});
}

TEST_F(ObjLoaderTest, ForwardReferencesAreAllowed) {
  const Mesh mesh = load("fwd.obj", std::string("f 1 2 3\n") + kSquare);
  EXPECT_EQ(positionsOf(mesh), (Ints{0, 1, 2}));
}

TEST_F(ObjLoaderTest, MissingFile) {
  const fs::path path = dir_ / "nope.obj";
  Warnings warnings;
  try {
    loadObj(path, warnings);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path.string() + ": cannot open file");
  }
  try {
    loadObj(dir_, warnings);  // a folder
    FAIL() << "no error";
  } catch (const InputError& e) {
    expectMessage(e.what(), dir_, {": cannot open file"});
  }
}

TEST_F(ObjLoaderTest, MalformedNumbers) {
  const fs::path path = dir_ / "m.obj";
  expectMessage(loadError("v 0 0 0\nv 1 0 0\nv 1 abc 3\nf 1 2 3\n"), path,
                {":3: ", "malformed 'v' line", "'abc' is not a number"});
  expectMessage(loadError("v 0 0 0\nv 1 0 0\nv 1 2 3x\nf 1 2 3\n"), path, {":3: ", "'3x'"});
  expectMessage(loadError("v 0 0 0\nv 1 0 0\nv 1 2\nf 1 2 3\n"), path,
                {":3: ", "expected at least 3 numbers, got 2"});
  expectMessage(loadError("v 0 0 0\nv 1 0 0\nv\nf 1 2 3\n"), path, {":3: ", "got 0"});
  expectMessage(loadError(std::string(kSquare) + "vt 0.5 .\nf 1 2 3\n"), path,
                {":5: ", "malformed 'vt' line", "'.'"});
  expectMessage(loadError(std::string(kSquare) + "vn 0 0 1e\nf 1 2 3\n"), path,
                {":5: ", "malformed 'vn' line", "'1e'"});
  expectMessage(loadError(std::string(kSquare) + "f 1 x 3\n"), path,
                {":5: ", "malformed 'f' line", "'x'"});
  expectMessage(loadError(std::string(kSquare) + "f 1/ 2/ 3/\n"), path, {":5: ", "'1/'"});
  expectMessage(loadError(std::string(kSquare) + "f 1 2 3.0\n"), path, {":5: ", "'3.0'"});
  expectMessage(loadError(std::string(kSquare) + "f 1/1/1/1 2 3\n"), path, {":5: ", "'1/1/1/1'"});
  expectMessage(loadError(std::string(kSquare) + "f\n"), path, {":5: ", "face has no vertices"});
  // No inline comments: tinyobjloader would read "#" as one more corner.
  expectMessage(loadError(std::string(kSquare) + "f 1 2 3 # c\n"), path, {":5: ", "'#'"});
}

TEST_F(ObjLoaderTest, IndexZero) {
  const fs::path path = dir_ / "m.obj";
  const std::string head = std::string(kSquare) + "vt 0 0\nvn 0 0 1\n";  // lines 1-6
  expectMessage(loadError(head + "f 1 0 3\n"), path, {":7: ", "vertex index 0 is invalid"});
  expectMessage(loadError(head + "f 1/1 2/0 3/1\n"), path,
                {":7: ", "texture coordinate index 0 is invalid"});
  expectMessage(loadError(head + "f 1//1 2//1 3//-0\n"), path, {":7: ", "normal index 0"});
}

TEST_F(ObjLoaderTest, IndexOutOfRange) {
  const fs::path path = dir_ / "m.obj";
  const std::string head = std::string(kSquare) + "vt 0 0\nvn 0 0 1\n";  // lines 1-6
  expectMessage(loadError(head + "f 1 2 3\nf 1 12 3\n"), path,
                {":8: ", "vertex index 12 out of range (model has 4 vertices)"});
  expectMessage(loadError(head + "f 1 -5 3\n"), path,
                {":7: ", "vertex index -5 out of range (4 vertices defined before this line)"});
  expectMessage(loadError(head + "f 1/2 2/1 3/1\n"), path,
                {":7: ", "texture coordinate index 2 out of range (model has 1 texture"});
  expectMessage(loadError(head + "f 1/-2 2/1 3/1\n"), path,
                {":7: ", "texture coordinate index -2 out of range"});
  expectMessage(loadError(head + "f 1//1 2//3 3//1\n"), path,
                {":7: ", "normal index 3 out of range (model has 1 normals)"});
  expectMessage(loadError(head + "f 1//1 2//-2 3//1\n"), path, {":7: ", "normal index -2 out"});
  // A negative index cannot reach a vertex defined after its line.
  expectMessage(loadError("v 0 0 0\nf -1 -2 -1\nv 1 0 0\n"), path,
                {":2: ", "vertex index -2 out of range"});
  // Beyond int32: refused, not wrapped by atoi.
  expectMessage(loadError(head + "f 1 2 4294967297\n"), path,
                {":7: ", "vertex index 4294967297 out of range"});
}

TEST_F(ObjLoaderTest, NonFiniteCoordinates) {
  const fs::path path = dir_ / "m.obj";
  expectMessage(loadError(std::string(kSquare) + "v nan 0 0\nf 1 2 3\n"), path,
                {":5: ", "NaN or infinite coordinate 'nan'"});
  expectMessage(loadError(std::string(kSquare) + "vt 0 -Inf\nf 1 2 3\n"), path,
                {":5: ", "NaN or infinite coordinate '-Inf'"});
  expectMessage(loadError(std::string(kSquare) + "vn 0 0 -1.#IND\nf 1 2 3\n"), path,
                {":5: ", "NaN or infinite"});
  // Well-formed numbers that overflow a double, found by tinyobjloader's values.
  expectMessage(loadError(std::string(kSquare) + "f 1 2 3\nv 1e400 0 0\n"), path,
                {":6: ", "NaN or infinite coordinate"});
  expectMessage(
      loadError(std::string(kSquare) + "vt 0 0\nvt 0 " + std::string(400, '9') + "\nf 1 2 3\n"),
      path, {":6: ", "NaN or infinite coordinate"});
  expectMessage(loadError(std::string(kSquare) + "vn 0 0 1\nf 1 2 3\nvn 1e-999999 0 0\n"), path,
                {":7: ", "out of range"});
}

TEST_F(ObjLoaderTest, NoFaces) {
  const fs::path path = dir_ / "m.obj";
  EXPECT_EQ(loadError(std::string(kSquare) + "l 1 2\np 3\n"),
            path.string() + ": model has no faces");
  EXPECT_EQ(loadError(""), path.string() + ": model has no faces");
  EXPECT_EQ(loadError("\xEF\xBB\xBF"), path.string() + ": model has no faces");
}

TEST_F(ObjLoaderTest, TooManyCorners) {
  std::string obj = kSquare;
  obj += "f";
  for (uint32_t i = 0; i <= kMaxFaceCorners; ++i) obj += " " + std::to_string(i % 4 + 1);
  obj += "\n";
  expectMessage(loadError(obj), dir_ / "m.obj", {":5: ", "more than 4096 corners"});
}

TEST_F(ObjLoaderTest, BinaryGarbageIsACleanError) {
  uint32_t state = 12345;
  auto next = [&state] {
    state = state * 1664525u + 1013904223u;
    return static_cast<char>(state >> 24);
  };
  for (int round = 0; round < 20; ++round) {
    std::string bytes;
    for (int i = 0; i < 20000; ++i) {
      // Some rounds plant statement keywords among the garbage.
      if (round % 2 == 1 && i % 97 == 0) bytes += (i % 3 == 0) ? "\nf " : "\nv ";
      bytes += next();
    }
    const std::string message = loadError(bytes);
    EXPECT_EQ(message.rfind((dir_ / "m.obj").string() + ":", 0), 0u) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST_F(ObjLoaderTest, StanfordBunny) {
  const fs::path path = ZRENDER_SOURCE_DIR "/models/bunny/bunny.obj";
  if (!fs::exists(path)) GTEST_SKIP() << path << " not present";
  Warnings warnings;
  const Mesh mesh = loadObj(path, warnings);
  EXPECT_EQ(mesh.faceCount(), 69451u);
  EXPECT_EQ(mesh.positions.size(), 35947u);
  EXPECT_EQ(mesh.corners.size(), 3u * 69451u);
  EXPECT_TRUE(warnings.empty());
}

}  // namespace
}  // namespace zrender
