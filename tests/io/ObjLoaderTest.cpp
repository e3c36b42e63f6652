// The OBJ loader (docs/design.md, Models): faces, corners, indices, materials and textures as the
// file gives them, in file order with their ids kept; the text variants exporters write; the
// reference bunny.

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "support/ObjLoaderFixture.hpp"
#include "zrender/io/obj/ObjLoader.hpp"
#include "zrender/scene/Mesh.hpp"

namespace zrender {
namespace {

using ObjLoader = test::ObjLoaderFixture;
using test::expectMessage;
using test::kSquareVertices;
namespace fs = std::filesystem;

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

TEST_F(ObjLoader, Triangle) {
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

TEST_F(ObjLoader, TriangleThenQuad) {
  const Mesh mesh = load("q.obj", std::string(kSquareVertices) +
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

TEST_F(ObjLoader, NegativeIndicesCountBackFromTheLineBefore) {
  // The first face sees 4 vertices (-4 -> 0); the second sees 5 (-1 -> 4, -5 -> 0).
  const Mesh mesh = load("n.obj", std::string(kSquareVertices) +
                                      "f -4 -3 -2 -1\n"
                                      "v 2 2 0\n"
                                      "f -1 -5 -2\n");
  ASSERT_EQ(mesh.faceCount(), 2u);
  EXPECT_EQ(positionsOf(mesh), (Ints{0, 1, 2, 3, 4, 0, 3}));
}

TEST_F(ObjLoader, TexcoordAndNormalIndices) {
  const Mesh mesh = load("tn.obj", std::string(kSquareVertices) +
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

TEST_F(ObjLoader, ConcaveHexagonStaysOneFace) {
  // An L shape: six corners, concave at (1, 1).
  const Mesh mesh = load("l.obj",
                         "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\n"
                         "f 1 2 3 4 5 6\n");
  ASSERT_EQ(mesh.faceCount(), 1u);
  EXPECT_EQ(mesh.faceStart, (Offsets{0, 6}));
  EXPECT_EQ(positionsOf(mesh), (Ints{0, 1, 2, 3, 4, 5}));
}

TEST_F(ObjLoader, DegenerateFacesKeepTheirIds) {
  // tinyobjloader's shapes would drop the 1- and 2-corner faces and renumber the triangle.
  const Mesh mesh = load("d.obj", std::string(kSquareVertices) +
                                      "f 1\n"
                                      "f 1 2\n"
                                      "f 2 3 4\n");
  ASSERT_EQ(mesh.faceCount(), 3u);
  EXPECT_EQ(mesh.faceStart, (Offsets{0, 1, 3, 6}));
  EXPECT_EQ(positionsOf(mesh), (Ints{0, 0, 1, 1, 2, 3}));
}

TEST_F(ObjLoader, LargeFacesKeepAllCorners) {
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

TEST_F(ObjLoader, FacesStayInFileOrderAcrossGroupsObjectsAndMaterials) {
  write("m.mtl", "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n");
  const Mesh mesh = load("order.obj", std::string("mtllib m.mtl\n") + kSquareVertices +
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

TEST_F(ObjLoader, MaterialWithTexture) {
  write("tex.png", "not really a png; only its existence matters here");
  write("m.mtl",
        "# materials\n"
        "newmtl plain\n"
        "Kd 0.5 0.25 1\n"
        "newmtl textured\n"
        "Kd 1 1 1\n"
        "map_Kd tex.png\n");
  const Mesh mesh = load("m.obj", std::string("mtllib m.mtl\n") + kSquareVertices +
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
TEST_F(ObjLoader, TexturePathWithBackslashes) {
  fs::create_directories(dir_ / "maps");
  write("maps/wood.png", "only its existence matters here");
  write("m.mtl", "newmtl wood\nmap_Kd maps\\wood.png\n");
  Warnings warnings;
  const Mesh mesh = loadObj(
      write("m.obj", std::string("mtllib m.mtl\nusemtl wood\n") + kSquareVertices + "f 1 2 3\n"),
      warnings);
  ASSERT_EQ(mesh.materials.size(), 1u);
  EXPECT_EQ(mesh.materials[0].diffuseTexture, (dir_ / "maps/wood.png").string());
  EXPECT_TRUE(warnings.empty());
}

TEST_F(ObjLoader, MissingMtlIsAWarning) {
  Warnings warnings;
  const Mesh mesh = loadObj(
      write("m.obj", std::string("mtllib gone.mtl\nusemtl red\n") + kSquareVertices + "f 1 2 3\n"),
      warnings);
  EXPECT_EQ(mesh.faceCount(), 1u);
  EXPECT_EQ(mesh.faceMaterial, (Ints{-1}));
  EXPECT_TRUE(mesh.materials.empty());
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], (dir_ / "m.obj").string() + ": material file 'gone.mtl' not found");
}

TEST_F(ObjLoader, MissingTextureIsAWarning) {
  write("m.mtl", "newmtl skin\nKd 1 0.5 0\nmap_Kd missing.png\n");
  Warnings warnings;
  const Mesh mesh = loadObj(
      write("m.obj", std::string("mtllib m.mtl\nusemtl skin\n") + kSquareVertices + "f 1 2 3\n"),
      warnings);
  ASSERT_EQ(mesh.materials.size(), 1u);
  EXPECT_EQ(mesh.materials[0].diffuseTexture, "");
  EXPECT_FLOAT_EQ(mesh.materials[0].diffuse[1], 0.5f);
  EXPECT_EQ(mesh.faceMaterial, (Ints{0}));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], (dir_ / "m.obj").string() + ": texture 'missing.png' not found");
}

TEST_F(ObjLoader, UnknownMaterialNameIsAWarning) {
  write("m.mtl", "newmtl red\nKd 1 0 0\n");
  Warnings warnings;
  const Mesh mesh = loadObj(
      write("m.obj", std::string("mtllib m.mtl\nusemtl green\n") + kSquareVertices + "f 1 2 3\n"),
      warnings);
  EXPECT_EQ(mesh.faceMaterial, (Ints{-1}));
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], (dir_ / "m.obj").string() + ": material 'green' not found");
}

TEST_F(ObjLoader, CrlfTabsBomAndNoFinalNewline) {
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

TEST_F(ObjLoader, NonUtf8CommentsAndGroupNames) {
  const Mesh mesh = load("c.obj", std::string("# \xFF\xFE caf\xE9\n") + kSquareVertices +
                                      "g \xFF\xFE\x01\n"
                                      "f 1 2 3\n"
                                      "\x7F\x80 unknown statement\n");
  EXPECT_EQ(mesh.faceCount(), 1u);
}

TEST_F(ObjLoader, MultiMegabyteLines) {
  const std::string longComment = "# " + std::string(4u << 20, 'x') + "\n";
  const Mesh mesh = load("long.obj", longComment + kSquareVertices + "o " +
                                         std::string(3u << 20, 'y') + "\nf 1 2 3\n");
  EXPECT_EQ(mesh.faceCount(), 1u);
  // A multi-megabyte face line is refused for its corner count, with its line number.
  std::string face = "f";
  for (int i = 0; i < 500000; ++i) face += " 1 2 3 4";
  expectMessage(loadError(std::string(kSquareVertices) + face + "\n"), dir_ / "m.obj",
                {":5: ", "more than 4096 corners"});
}

TEST_F(ObjLoader, ForwardReferencesAreAllowed) {
  const Mesh mesh = load("fwd.obj", std::string("f 1 2 3\n") + kSquareVertices);
  EXPECT_EQ(positionsOf(mesh), (Ints{0, 1, 2}));
}

TEST_F(ObjLoader, StanfordBunny) {
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
