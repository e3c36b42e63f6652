// The model formats beyond OBJ (io/models): the same geometry written by the test as OBJ, PLY
// (ASCII and binary), OFF, STL (ASCII and binary) and glTF (.gltf with its .bin, and .glb) gives
// the same face ids, depths and colors with every algorithm; each format's material path
// against OBJ's MTL and against a pixel computed by hand; content that is not what the
// extension says, and truncated files, against their messages.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "support/TestImages.hpp"
#include "support/TestSupport.hpp"
#include "zrender/base/Error.hpp"
#include "zrender/io/SceneFiles.hpp"
#include "zrender/io/models/ModelFormats.hpp"
#include "zrender/io/models/ModelLoader.hpp"
#include "zrender/visibility/VisibilityAlgorithm.hpp"

namespace zrender {
namespace {

// Geometry as the test writes it: positions (halves, exact in float as assimp keeps them) and
// faces of position indices; per position an optional RGB color (0..255).
struct Geometry {
  std::vector<Vec3> positions;
  std::vector<std::vector<int>> faces;
  std::vector<cv::Vec3b> colors;  // per position, or empty
};

// Three boxes that hide each other in part, each face a quad wound outwards; no two boxes share
// a corner's position (STL's corners are joined by position).
Geometry boxes() {
  Geometry g;
  const double corners[3][4] = {{-1.0, -1.0, -1.0, 1.5},
                                {0.0, -0.5, -0.5, 1.0},
                                {-0.5, 0.25, 0.5, 0.5}};  // x, y, z of the low corner, side
  for (const auto& c : corners) {
    const int base = int(g.positions.size());
    for (int k = 0; k < 8; ++k) {
      g.positions.emplace_back(c[0] + (k & 1 ? c[3] : 0.0), c[1] + (k & 2 ? c[3] : 0.0),
                               c[2] + (k & 4 ? c[3] : 0.0));
    }
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                             {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads)
      g.faces.push_back({base + q[0], base + q[1], base + q[2], base + q[3]});
  }
  return g;
}

// The same with each quad cut into two triangles (a, b, c) and (a, c, d).
Geometry triangles(const Geometry& quads) {
  Geometry g = quads;
  g.faces.clear();
  for (const auto& f : quads.faces) {
    g.faces.push_back({f[0], f[1], f[2]});
    g.faces.push_back({f[0], f[2], f[3]});
  }
  return g;
}

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", v);
  return text;
}

std::string objText(const Geometry& g, const std::string& header = "",
                    const std::vector<std::string>& faceLines = {}) {
  std::string s = header;
  for (const Vec3& p : g.positions)
    s += "v " + number(p[0]) + " " + number(p[1]) + " " + number(p[2]) + "\n";
  for (size_t f = 0; f < g.faces.size(); ++f) {
    if (f < faceLines.size() && !faceLines[f].empty()) s += faceLines[f] + "\n";
    s += "f";
    for (int i : g.faces[f]) s += " " + std::to_string(i + 1);
    s += "\n";
  }
  return s;
}

std::string plyHeader(const Geometry& g, const std::string& format) {
  std::string s = "ply\nformat " + format + " 1.0\nelement vertex " +
                  std::to_string(g.positions.size()) +
                  "\nproperty float x\nproperty float y\nproperty float z\n";
  if (!g.colors.empty()) s += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  s += "element face " + std::to_string(g.faces.size()) +
       "\nproperty list uchar int vertex_indices\nend_header\n";
  return s;
}

std::string plyAscii(const Geometry& g) {
  std::string s = plyHeader(g, "ascii");
  for (size_t v = 0; v < g.positions.size(); ++v) {
    const Vec3& p = g.positions[v];
    s += number(p[0]) + " " + number(p[1]) + " " + number(p[2]);
    if (!g.colors.empty())
      for (int c = 0; c < 3; ++c) s += " " + std::to_string(int(g.colors[v][c]));
    s += "\n";
  }
  for (const auto& f : g.faces) {
    s += std::to_string(f.size());
    for (int i : f) s += " " + std::to_string(i);
    s += "\n";
  }
  return s;
}

template <typename T>
void append(std::string& s, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  s.append(bytes, sizeof(T));
}

std::string plyBinary(const Geometry& g) {
  std::string s = plyHeader(g, "binary_little_endian");
  for (size_t v = 0; v < g.positions.size(); ++v) {
    for (int a = 0; a < 3; ++a) append(s, float(g.positions[v][a]));
    if (!g.colors.empty())
      for (int c = 0; c < 3; ++c) append(s, uint8_t(g.colors[v][c]));
  }
  for (const auto& f : g.faces) {
    append(s, uint8_t(f.size()));
    for (int i : f) append(s, int32_t(i));
  }
  return s;
}

std::string offText(const Geometry& g) {
  std::string s =
      "OFF\n" + std::to_string(g.positions.size()) + " " + std::to_string(g.faces.size()) + " 0\n";
  for (const Vec3& p : g.positions)
    s += number(p[0]) + " " + number(p[1]) + " " + number(p[2]) + "\n";
  for (const auto& f : g.faces) {
    s += std::to_string(f.size());
    for (int i : f) s += " " + std::to_string(i);
    s += "\n";
  }
  return s;
}

std::string stlAscii(const Geometry& g) {
  std::string s = "solid test\n";
  for (const auto& f : g.faces) {
    s += " facet normal 0 0 0\n  outer loop\n";
    for (int i : f) {
      const Vec3& p = g.positions[size_t(i)];
      s += "   vertex " + number(p[0]) + " " + number(p[1]) + " " + number(p[2]) + "\n";
    }
    s += "  endloop\n endfacet\n";
  }
  return s + "endsolid test\n";
}

std::string stlBinary(const Geometry& g) {
  std::string s(80, ' ');
  s.replace(0, 11, "binary test");
  append(s, uint32_t(g.faces.size()));
  for (const auto& f : g.faces) {
    for (int a = 0; a < 3; ++a) append(s, 0.0f);
    for (int i : f)
      for (int a = 0; a < 3; ++a) append(s, float(g.positions[size_t(i)][a]));
    append(s, uint16_t(0));
  }
  return s;
}

// What a glTF file holds beyond the triangles: texture coordinates per position, a material's
// base color factor, and its base color texture (a PNG file's bytes).
struct GltfExtras {
  std::string nodes = "[{\"mesh\":0}]";  // the "nodes" array: one node showing the mesh
  std::vector<cv::Vec2f> uvs;            // glTF's: v down from the image's top
  std::vector<double> baseColor;         // r, g, b, a, or empty for no material
  std::vector<unsigned char> png;        // the texture, or empty
};

// The JSON and the binary buffer of a glTF of triangles `g`; `uri` names the buffer (empty in
// a .glb, where it follows the JSON).
void gltfParts(const Geometry& g, const GltfExtras& extras, const std::string& uri,
               std::string& json, std::string& bin) {
  bin.clear();
  for (const Vec3& p : g.positions)
    for (int a = 0; a < 3; ++a) append(bin, float(p[a]));
  const size_t positionBytes = bin.size();
  for (const cv::Vec2f& t : extras.uvs) append(bin, t[0]), append(bin, t[1]);
  const size_t uvBytes = bin.size() - positionBytes;
  size_t indexCount = 0;
  for (const auto& f : g.faces)
    for (int i : f) append(bin, uint32_t(i)), ++indexCount;
  const size_t indexBytes = indexCount * 4;
  const size_t imageOffset = bin.size();
  bin.append(extras.png.begin(), extras.png.end());
  while (bin.size() % 4) bin.push_back('\0');

  Vec3 lo = g.positions[0], hi = g.positions[0];
  for (const Vec3& p : g.positions)
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], p[a]), hi[a] = std::max(hi[a], p[a]);
  const std::string n = std::to_string(g.positions.size());
  std::string views =
      "{\"buffer\":0,\"byteOffset\":0,\"byteLength\":" + std::to_string(positionBytes) + "}";
  std::string accessors = "{\"bufferView\":0,\"componentType\":5126,\"count\":" + n +
                          ",\"type\":\"VEC3\",\"min\":[" + number(lo[0]) + "," + number(lo[1]) +
                          "," + number(lo[2]) + "],\"max\":[" + number(hi[0]) + "," +
                          number(hi[1]) + "," + number(hi[2]) + "]}";
  views += ",{\"buffer\":0,\"byteOffset\":" + std::to_string(positionBytes + uvBytes) +
           ",\"byteLength\":" + std::to_string(indexBytes) + "}";
  accessors += ",{\"bufferView\":1,\"componentType\":5125,\"count\":" + std::to_string(indexCount) +
               ",\"type\":\"SCALAR\"}";
  std::string attributes = "\"POSITION\":0";
  if (!extras.uvs.empty()) {
    views += ",{\"buffer\":0,\"byteOffset\":" + std::to_string(positionBytes) +
             ",\"byteLength\":" + std::to_string(uvBytes) + "}";
    accessors += ",{\"bufferView\":2,\"componentType\":5126,\"count\":" + n + ",\"type\":\"VEC2\"}";
    attributes += ",\"TEXCOORD_0\":2";
  }
  std::string material, textures;
  if (!extras.baseColor.empty()) {
    std::string factor;
    for (double c : extras.baseColor) factor += (factor.empty() ? "" : ",") + number(c);
    std::string texture;
    if (!extras.png.empty()) {
      views += ",{\"buffer\":0,\"byteOffset\":" + std::to_string(imageOffset) +
               ",\"byteLength\":" + std::to_string(extras.png.size()) + "}";
      const int view = extras.uvs.empty() ? 2 : 3;
      textures = ",\"images\":[{\"bufferView\":" + std::to_string(view) +
                 ",\"mimeType\":\"image/png\"}],\"textures\":[{\"source\":0}]";
      texture = ",\"baseColorTexture\":{\"index\":0}";
    }
    material = ",\"materials\":[{\"name\":\"m\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[" +
               factor + "]" + texture + "}}]";
  }
  json =
      "{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scenes\":[{\"nodes\":[0]}],"
      "\"nodes\":" +
      extras.nodes + ",\"meshes\":[{\"primitives\":[{\"attributes\":{" + attributes +
      "},\"indices\":1" + (material.empty() ? "" : ",\"material\":0") + "}]}],\"accessors\":[" +
      accessors + "],\"bufferViews\":[" + views + "],\"buffers\":[{" +
      (uri.empty() ? "" : "\"uri\":\"" + uri + "\",") +
      "\"byteLength\":" + std::to_string(bin.size()) + "}]" + material + textures + "}";
}

std::string glb(const std::string& json, const std::string& bin) {
  std::string paddedJson = json;
  while (paddedJson.size() % 4) paddedJson.push_back(' ');
  std::string s = "glTF";
  append(s, uint32_t(2));
  append(s, uint32_t(12 + 8 + paddedJson.size() + 8 + bin.size()));
  append(s, uint32_t(paddedJson.size()));
  append(s, uint32_t(0x4E4F534A));  // JSON
  s += paddedJson;
  append(s, uint32_t(bin.size()));
  append(s, uint32_t(0x004E4942));  // BIN
  return s + bin;
}

SceneSettings settingsFor(const std::string& path, ShadingMode shading) {
  SceneSettings s = test::tinySettings(48);
  s.modelPath = path;
  s.angle = 35.0;
  s.axis = cv::Vec3d(1.0, 2.0, 0.5);
  s.shading = shading;
  return s;
}

Scene load(const std::string& path, ShadingMode shading, Warnings* warningsOut = nullptr) {
  Warnings warnings;
  Scene scene = loadScene(settingsFor(path, shading), warnings);
  if (warningsOut)
    *warningsOut = warnings;
  else
    EXPECT_TRUE(warnings.empty()) << path << ": " << warnings.front();
  return scene;
}

// Every algorithm draws `other` as it draws `reference`: keys and colors, bit for bit.
void expectSameScenes(const Scene& reference, const Scene& other, const std::string& label) {
  ASSERT_EQ(reference.faceCount(), other.faceCount()) << label;
  for (const std::string& algorithm : algorithmNames()) {
    const test::Rendered a = test::render(reference, algorithm);
    const test::Rendered b = test::render(other, algorithm);
    ASSERT_GT(test::coveredSamples(a.buffer), 200u);
    test::expectSameFrame(a, b, label + " " + algorithm);
  }
}

TEST(ModelFormats, PolygonsReadTheSameFromObjPlyAndOff) {
  const test::TempDir dir;
  const Geometry g = boxes();
  const Scene obj = load(dir.write("m.obj", objText(g)), ShadingMode::Phong);
  ASSERT_EQ(obj.mesh->faceCount(), 18u);
  const std::pair<const char*, std::string> files[] = {
      {"m.ply", plyAscii(g)}, {"binary.ply", plyBinary(g)}, {"m.off", offText(g)}};
  for (const auto& [name, text] : files) {
    const Scene other = load(dir.write(name, text), ShadingMode::Phong);
    EXPECT_EQ(other.mesh->cornerCount(0), 4u) << name << ": quads stay quads";
    expectSameScenes(obj, other, name);
  }
}

TEST(ModelFormats, TrianglesReadTheSameFromObjStlAndGltf) {
  const test::TempDir dir;
  const Geometry g = triangles(boxes());
  const Scene obj = load(dir.write("t.obj", objText(g)), ShadingMode::Phong);
  std::string json, bin;
  gltfParts(g, GltfExtras(), "t.bin", json, bin);
  dir.write("t.bin", bin);
  std::string glbJson, glbBin;
  gltfParts(g, GltfExtras(), "", glbJson, glbBin);
  const std::pair<const char*, std::string> files[] = {{"t.stl", stlAscii(g)},
                                                       {"binary.stl", stlBinary(g)},
                                                       {"t.ply", plyBinary(g)},
                                                       {"t.gltf", json},
                                                       {"t.glb", glb(glbJson, glbBin)}};
  for (const auto& [name, text] : files) {
    expectSameScenes(obj, load(dir.write(name, text), ShadingMode::Phong), name);
  }
}

// PLY vertex colors are the faces' base colors: the same frame as an OBJ whose faces use two
// MTL materials of those colors (51/255 is the float nearest 0.2, as "0.2" is).
TEST(ModelFormats, PlyVertexColorsShadeAsMtlMaterials) {
  const test::TempDir dir;
  Geometry g = boxes();
  const cv::Vec3b first(51, 102, 153), second(204, 153, 51);
  for (size_t v = 0; v < g.positions.size(); ++v) g.colors.push_back(v < 8 ? first : second);
  dir.write("m.mtl", "newmtl a\nKd 0.2 0.4 0.6\nnewmtl b\nKd 0.8 0.6 0.2\n");
  std::vector<std::string> uses(g.faces.size());
  uses[0] = "usemtl a";
  uses[6] = "usemtl b";
  const Scene obj =
      load(dir.write("m.obj", objText(g, "mtllib m.mtl\n", uses)), ShadingMode::Phong);
  ASSERT_EQ(obj.mesh->materials.size(), 2u);
  for (const char* name : {"c.ply", "binary.ply"}) {
    const std::string text = std::string(name) == "c.ply" ? plyAscii(g) : plyBinary(g);
    expectSameScenes(obj, load(dir.write(name, text), ShadingMode::Phong), name);
  }
}

// A square facing the eye across the image's centre, as glTF with a base color factor: at the
// centre sample (9 x 9 samples, the ray along -z) the light is 1 and the specular 1, so a
// channel is factor x 255 + 0.3 x 255, rounded and clamped: 0.25 -> 140.25 -> 140,
// 0.5 -> 204, 0.75 -> 267.75 -> 255.
TEST(ModelFormats, GltfBaseColorFactorLightsTheCentrePixel) {
  const test::TempDir dir;
  Geometry g;
  g.positions = {Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0)};
  g.faces = {{0, 1, 2}, {0, 2, 3}};
  GltfExtras extras;
  extras.baseColor = {0.25, 0.5, 0.75, 1.0};
  std::string json, bin;
  gltfParts(g, extras, "", json, bin);
  SceneSettings settings = test::tinySettings(9);
  settings.modelPath = dir.write("q.glb", glb(json, bin));
  settings.shading = ShadingMode::Phong;
  Warnings warnings;
  const Scene scene = loadScene(settings, warnings);
  ASSERT_EQ(scene.mesh->materials.size(), 1u);
  const test::Rendered r = test::render(scene, "zbuffer");
  EXPECT_EQ(r.color.at<cv::Vec3b>(4, 4), cv::Vec3b(255, 204, 140));  // B, G, R
}

// glTF's base color is the texture times the factor, and its v runs down from the image's top:
// the same frame as an OBJ whose map_Kd is that product and whose v is 1 - v.
TEST(ModelFormats, GltfTextureTimesFactorMatchesObjMapKd) {
  const test::TempDir dir;
  const Geometry g = triangles(boxes());
  cv::Mat texture(2, 2, CV_8UC3);
  texture.at<cv::Vec3b>(0, 0) = cv::Vec3b(200, 40, 100);
  texture.at<cv::Vec3b>(0, 1) = cv::Vec3b(20, 220, 60);
  texture.at<cv::Vec3b>(1, 0) = cv::Vec3b(120, 80, 240);
  texture.at<cv::Vec3b>(1, 1) = cv::Vec3b(60, 160, 20);
  const cv::Vec3f factor(0.5f, 1.0f, 0.5f);  // r, g, b: even texels halve exactly
  cv::Mat product = texture.clone();
  product.forEach<cv::Vec3b>([&](cv::Vec3b& t, const int*) {
    for (int c = 0; c < 3; ++c) t[c] = uint8_t(t[c] * factor[2 - c]);
  });
  ASSERT_TRUE(test::imwrite(dir.file("product.png"), product));
  GltfExtras extras;
  extras.baseColor = {factor[0], factor[1], factor[2], 1.0};
  ASSERT_TRUE(test::imencode(".png", texture, extras.png));
  std::string obj = "mtllib m.mtl\nusemtl t\n";
  for (size_t v = 0; v < g.positions.size(); ++v) {
    const float u = float(v % 5) * 0.25f, w = float(v % 3) * 0.5f;  // exact in float
    extras.uvs.emplace_back(u, w);
    obj += "vt " + number(u) + " " + number(1.0 - w) + "\n";
  }
  for (const Vec3& p : g.positions)
    obj += "v " + number(p[0]) + " " + number(p[1]) + " " + number(p[2]) + "\n";
  for (const auto& f : g.faces) {
    obj += "f";
    for (int i : f) obj += " " + std::to_string(i + 1) + "/" + std::to_string(i + 1);
    obj += "\n";
  }
  dir.write("m.mtl", "newmtl t\nKd 1 1 1\nmap_Kd product.png\n");
  const Scene reference = load(dir.write("t.obj", obj), ShadingMode::Texture);
  ASSERT_FALSE(reference.materialTextures.at(0).empty());
  std::string json, bin;
  gltfParts(g, extras, "", json, bin);
  const Scene embedded = load(dir.write("t.glb", glb(json, bin)), ShadingMode::Texture);
  ASSERT_FALSE(embedded.materialTextures.at(0).empty());
  expectSameScenes(reference, embedded, "glb");
}

void expectLoadError(const std::string& path, const std::string& message) {
  Warnings warnings;
  try {
    loadModel(path, warnings);
    ADD_FAILURE() << path << ": no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind(message, 0), 0u) << e.what();
  }
}

TEST(ModelFormats, ContentThatIsNotTheExtensionsFormatIsNamed) {
  const test::TempDir dir;
  std::vector<unsigned char> png;
  ASSERT_TRUE(test::imencode(".png", cv::Mat(2, 2, CV_8UC3, cv::Scalar(1, 2, 3)), png));
  const std::string pngBytes(png.begin(), png.end());
  const std::string list = "; zrender reads: obj, ply, stl, off, gltf, glb, fbx, dae, 3ds";
  const std::string ply = dir.write("x.ply", pngBytes);
  expectLoadError(ply, ply + ": not a PLY file (looks like a PNG image)" + list);
  const std::string obj = dir.write("x.obj", pngBytes);
  expectLoadError(obj, obj + ": not an OBJ file (looks like a PNG image)" + list);
  const std::string stl = dir.write("x.stl", plyAscii(boxes()));
  expectLoadError(stl, stl + ": not an STL file (looks like a PLY model)" + list);
  const std::string off = dir.write("x.off", "{\"asset\": {}}");
  expectLoadError(off, off + ": not an OFF file (looks like a glTF model)" + list);
  const std::string unknown = dir.write("x.xyz", "v 0 0 0\n");
  expectLoadError(unknown, unknown + ": unknown model format '.xyz'" + list);
  const std::string empty = dir.write("e.glb", "");
  expectLoadError(empty, empty + ": not a glTF file (looks like an empty file)" + list);
}

// A file cut short, at every tenth of its length, is refused with a message that names it,
// whichever check catches it (the content's or the reader's).
TEST(ModelFormats, TruncatedFilesAreRefusedCleanly) {
  const test::TempDir dir;
  const Geometry g = triangles(boxes());
  std::string json, bin;
  gltfParts(g, GltfExtras(), "", json, bin);
  const std::pair<const char*, std::string> files[] = {
      {"t.ply", plyBinary(g)}, {"a.ply", plyAscii(g)}, {"t.stl", stlBinary(g)},
      {"a.stl", stlAscii(g)},  {"t.off", offText(g)},  {"t.glb", glb(json, bin)}};
  for (const auto& [name, text] : files) {
    for (int tenth = 0; tenth < 10; ++tenth) {
      const std::string path = dir.write(name, text.substr(0, text.size() * tenth / 10));
      Warnings warnings;
      try {
        const Mesh mesh = loadModel(path, warnings);
        // Text formats may end at a line that leaves a smaller whole model.
        EXPECT_LT(mesh.faceCount(), g.faces.size()) << name << " cut at " << tenth << "/10";
      } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(path + ":", 0), 0u) << e.what();
      }
    }
  }
}

// assimp reserves what an OFF header announces before it reads a vertex: counts the file
// cannot hold are refused first, however they are written (leading zeros, more digits than 64
// bits hold, after an nOFF's dimension), and a file that holds its counts still loads.
TEST(ModelFormats, OffCountsBeyondTheFileAreRefused) {
  const test::TempDir dir;
  const std::string tail = "\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  const auto expectRefused = [&](const std::string& header, const std::string& counts) {
    const std::string text = header + tail;
    const std::string path = dir.write("big.off", text);
    expectLoadError(path, path + ": its OFF header announces " + counts + ", more than its " +
                              std::to_string(text.size()) + " bytes can hold");
  };
  expectRefused("OFF\n4000000000 1 0", "4000000000 vertices and 1 faces");
  expectRefused("OFF\n3 4000000000 0", "3 vertices and 4000000000 faces");
  // The fuzzer's find: 19 leading zeros hid the count from a check that read 19 digits.
  expectRefused("OFF\n" + std::string(40, '0') + "2049638230412172402 2 0",
                "2049638230412172402 vertices and 2 faces");
  expectRefused("OFF\n3 " + std::string(30, '9') + " 0",
                "3 vertices and 18446744073709551615 or more faces");
  expectRefused("nOFF\n3\n3 4000000000 0", "3 vertices and 4000000000 faces");
  expectRefused("OFF # comment\n# more\n4000000000 1 0", "4000000000 vertices and 1 faces");
  // The fuzzer's second find: the keyword after a space.
  expectRefused("  \n OFF 4000000000 1 0", "4000000000 vertices and 1 faces");
  expectRefused("\xEF\xBB\xBF OFF 4000000000 1 0", "4000000000 vertices and 1 faces");
  Warnings warnings;
  EXPECT_EQ(loadModel(dir.write("zeros.off", "OFF\n0003 0001 0" + tail), warnings).faceCount(), 1u);
}

// A PLY's vertices are read as parallel lists (positions, colors): a second 'vertex' element,
// with colors where the first had none, once read past the colors' end (found by fuzzing).
// Either element named twice is refused at its line.
TEST(ModelFormats, PlyElementsNamedTwiceAreRefused) {
  const test::TempDir dir;
  const std::string vertices =
      "element vertex 3\nproperty float x\nproperty float y\n"
      "property float z\n";
  const std::string colors = "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  const std::string faces = "element face 1\nproperty list uchar int vertex_indices\n";
  const std::string body =
      "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n0 0 0 9 9 9\n1 0 0 9 9 9\n"
      "0 1 0 9 9 9\n";
  const std::string twice = dir.write("v.ply", "ply\nformat ascii 1.0\n" + vertices + faces +
                                                   vertices + colors + "end_header\n" + body);
  expectLoadError(twice, twice + ":9: a second 'vertex' element in the PLY header");
  const std::string faceTwice = dir.write(
      "f.ply", "ply\nformat ascii 1.0\n" + vertices + faces + faces + "end_header\n" + body);
  expectLoadError(faceTwice, faceTwice + ":9: a second 'face' element in the PLY header");
}

TEST(ModelFormats, SniffingNamesCommonFiles) {
  EXPECT_EQ(sniffModelContent("ply\nformat ascii 1.0\n", 20).format, ModelFormat::Ply);
  EXPECT_EQ(sniffModelContent("OFF\n3 1 0\n", 10).format, ModelFormat::Off);
  EXPECT_EQ(sniffModelContent("COFF\n", 5).format, ModelFormat::Off);
  EXPECT_EQ(sniffModelContent("solid x\n", 8).format, ModelFormat::Stl);
  EXPECT_EQ(sniffModelContent("glTF\x02\0\0\0", 8).format, ModelFormat::Gltf);
  EXPECT_EQ(sniffModelContent("<?xml version=\"1.0\"?>\n<COLLADA>", 31).format,
            ModelFormat::Collada);
  EXPECT_EQ(sniffModelContent("# a model\nv 1 2 3\nf 1 1 1\n", 26).format, ModelFormat::Obj);
  EXPECT_EQ(sniffModelContent("\xFF\xD8\xFF\xE0", 4).looksLike, "a JPEG image");
  EXPECT_EQ(sniffModelContent(std::string("\0\1\2\3", 4), 4).looksLike, "binary data");
  EXPECT_EQ(sniffModelContent("hello\n", 6).looksLike, "text");
}

TEST(ModelFormats, TheFormatsOptionListsThem) {
  const test::RunResult r = test::runZrender({"--formats"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(test::beyondSummary(r.err), "");
  for (const char* ext : {".obj", ".ply", ".stl", ".off", ".gltf", ".glb", ".fbx", ".dae", ".3ds"})
    EXPECT_NE(r.out.find(std::string(" ") + ext + " "), std::string::npos) << ext;
}

// The command line: a PNG named .ply gets one line and exit 2, and a PLY renders as its OBJ.
TEST(ModelFormats, TheCommandLineSaysWhatAFileLooksLike) {
  const test::TempDir dir;
  std::vector<unsigned char> png;
  ASSERT_TRUE(test::imencode(".png", cv::Mat(2, 2, CV_8UC3, cv::Scalar(1, 2, 3)), png));
  const std::string path = dir.write("thing.ply", std::string(png.begin(), png.end()));
  const test::RunResult bad = test::runZrender({path, "-o", dir.file("out.png")});
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(bad.err, "zrender: error: " + path +
                         ": not a PLY file (looks like a PNG image); zrender reads: obj, ply, "
                         "stl, off, gltf, glb, fbx, dae, 3ds\n");
  EXPECT_FALSE(std::filesystem::exists(dir.file("out.png")));

  const Geometry g = boxes();
  const std::string obj = dir.write("m.obj", objText(g)), ply = dir.write("m.ply", plyBinary(g));
  const test::RunResult a = test::runZrender({obj, "--width", "64", "--height", "64", "--ids",
                                              dir.file("a.png"), "-o", dir.file("ca.png")});
  const test::RunResult b = test::runZrender({ply, "--width", "64", "--height", "64", "--ids",
                                              dir.file("b.png"), "-o", dir.file("cb.png")});
  ASSERT_EQ(a.status, 0) << a.err;
  ASSERT_EQ(b.status, 0) << b.err;
  EXPECT_EQ(test::beyondSummary(b.err), "");
  const std::string off = dir.write("m.off", offText(g));
  const test::RunResult c = test::runZrender({off, "--width", "64", "--height", "64", "--ids",
                                              dir.file("c.png"), "-o", dir.file("cc.png")});
  ASSERT_EQ(c.status, 0) << c.err;
  EXPECT_EQ(test::beyondSummary(c.err), "") << "assimp's log stays out of the terminal";
  EXPECT_EQ(test::readFile(dir.file("a.png")), test::readFile(dir.file("c.png")));
  EXPECT_EQ(test::readFile(dir.file("a.png")), test::readFile(dir.file("b.png")));
  EXPECT_EQ(test::readFile(dir.file("ca.png")), test::readFile(dir.file("cb.png")));
}

}  // namespace
}  // namespace zrender

namespace zrender {
namespace {

// Every file of assimp's own test models (Debian's assimp-testmodels) in a format zrender
// reads, malformed ones included: a model or a clean InputError naming the file, never a crash
// or another exception. tools/test.sh installs the package.
TEST(ModelFormats, AssimpTestModelsLoadOrFailCleanly) {
  const std::filesystem::path root = "/usr/share/assimp/models";
  if (!std::filesystem::is_directory(root)) GTEST_SKIP() << "assimp-testmodels not installed";
  size_t files = 0, loaded = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
    if (!entry.is_regular_file()) continue;
    const std::optional<ModelFormat> format = modelFormatOfPath(entry.path());
    if (!format || *format == ModelFormat::Obj) continue;
    ++files;
    const std::string path = entry.path().string();
    Warnings warnings;
    try {
      const Mesh mesh = loadModel(path, warnings);
      EXPECT_GT(mesh.faceCount(), 0u) << path;
      ++loaded;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind(path + ":", 0), 0u) << e.what();
    }
  }
  EXPECT_GT(files, 100u);
  EXPECT_GT(loaded, files / 2);
}

}  // namespace
}  // namespace zrender

namespace zrender {
namespace {

// Two squares side by side whose materials have textures of their own (MTL map_Kd): in the
// `texture` mode each square's pixels are those it has when its texture is the whole scene's.
TEST(ModelFormats, EachMaterialDrawsItsOwnTexture) {
  const test::TempDir dir;
  cv::Mat left(2, 2, CV_8UC3), right(2, 2, CV_8UC3);
  left.at<cv::Vec3b>(0, 0) = cv::Vec3b(200, 40, 100),
                        left.at<cv::Vec3b>(0, 1) = cv::Vec3b(10, 220, 60);
  left.at<cv::Vec3b>(1, 0) = cv::Vec3b(90, 80, 240),
                        left.at<cv::Vec3b>(1, 1) = cv::Vec3b(60, 160, 20);
  right = cv::Scalar(255, 255, 255) - left;
  ASSERT_TRUE(test::imwrite(dir.file("left.png"), left));
  ASSERT_TRUE(test::imwrite(dir.file("right.png"), right));
  dir.write("m.mtl", "newmtl l\nKd 1 1 1\nmap_Kd left.png\nnewmtl r\nKd 1 1 1\nmap_Kd right.png\n");
  const std::string obj = dir.write(
      "two.obj",
      "mtllib m.mtl\nv -1.5 -1 0\nv -0.1 -1 0\nv -0.1 1 0\nv -1.5 1 0\nv 0.1 -1 0\nv 1.5 -1 0\n"
      "v 1.5 1 0\nv 0.1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl l\nf 1/1 2/2 3/3 4/4\n"
      "usemtl r\nf 5/1 6/2 7/3 8/4\n");
  SceneSettings settings = test::tinySettings(40);
  settings.modelPath = obj;
  settings.shading = ShadingMode::Texture;
  Warnings warnings;
  const Scene both = loadScene(settings, warnings);
  ASSERT_TRUE(warnings.empty());
  ASSERT_EQ(both.materialTextures.size(), 2u);
  const test::Rendered r = test::render(both, "zbuffer");
  for (int side = 0; side < 2; ++side) {
    settings.texture = std::filesystem::path(dir.file(side == 0 ? "left.png" : "right.png"));
    const test::Rendered alone = test::render(loadScene(settings, warnings), "zbuffer");
    size_t compared = 0;
    for (int y = 0; y < 40; ++y) {
      for (int x = 0; x < 40; ++x) {
        const uint32_t id = keyFaceId(r.buffer.row(y)[x]);
        if (id != uint32_t(side)) continue;
        ++compared;
        ASSERT_EQ(r.color.at<cv::Vec3b>(y, x), alone.color.at<cv::Vec3b>(y, x))
            << "side " << side << " at " << x << ", " << y;
      }
    }
    EXPECT_GT(compared, 100u);
  }
}

}  // namespace
}  // namespace zrender

namespace zrender {
namespace {

// glTF node matrices: a node's translation and scale, and a child node's translation on top,
// give the faces the vertices an OBJ of the moved positions has (halves and doubles: exact).
TEST(ModelFormats, GltfNodeTransformsPlaceTheMesh) {
  const test::TempDir dir;
  const Geometry g = triangles(boxes());
  GltfExtras extras;
  extras.nodes =
      "[{\"children\":[1],\"translation\":[0.5,0,-1],\"scale\":[2,2,2]},"
      "{\"mesh\":0,\"translation\":[-0.25,0.5,0]}]";
  std::string json, bin;
  gltfParts(g, extras, "", json, bin);
  Geometry moved = g;
  for (Vec3& p : moved.positions) p = Vec3(0.5, 0, -1) + 2.0 * (p + Vec3(-0.25, 0.5, 0));
  SceneSettings settings = settingsFor(dir.write("m.obj", objText(moved)), ShadingMode::Phong);
  settings.eye = Vec3(0, 0, 6);
  Warnings warnings;
  const Scene reference = loadScene(settings, warnings);
  settings.modelPath = dir.write("m.glb", glb(json, bin));
  const Scene placed = loadScene(settings, warnings);
  EXPECT_TRUE(warnings.empty());
  expectSameScenes(reference, placed, "glb nodes");
}

}  // namespace
}  // namespace zrender
