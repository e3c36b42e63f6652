// Scenes of many objects (settings key "objects", or several model files on the command line):
// against the same geometry merged into one OBJ by the test, the face ids counting across the
// objects in list order, a file used twice read once, and placements.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "support/TestImages.hpp"
#include "support/TestSupport.hpp"
#include "zrender/base/Error.hpp"
#include "zrender/io/SceneFiles.hpp"
#include "zrender/io/settings/SettingsFile.hpp"
#include "zrender/render/Renderer.hpp"
#include "zrender/scene/Camera.hpp"
#include "zrender/visibility/VisibilityAlgorithm.hpp"

namespace zrender {
namespace {

struct Shape {
  std::vector<Vec3> positions;
  std::vector<std::vector<int>> faces;
};

// A box of side `side` from `lo` (quads wound outwards).
Shape box(const Vec3& lo, double side) {
  Shape s;
  for (int k = 0; k < 8; ++k)
    s.positions.emplace_back(lo[0] + (k & 1 ? side : 0.0), lo[1] + (k & 2 ? side : 0.0),
                             lo[2] + (k & 4 ? side : 0.0));
  s.faces = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  return s;
}

// A pyramid: a square base and four triangles.
Shape pyramid(const Vec3& lo, double side) {
  Shape s;
  s.positions = {lo, lo + Vec3(side, 0, 0), lo + Vec3(side, 0, side), lo + Vec3(0, 0, side),
                 lo + Vec3(side / 2, side, side / 2)};
  s.faces = {{0, 1, 2, 3}, {0, 4, 1}, {1, 4, 2}, {2, 4, 3}, {3, 4, 0}};
  return s;
}

std::string objOf(const std::vector<Shape>& shapes) {
  std::string text;
  int base = 1;
  for (const Shape& s : shapes) {
    for (const Vec3& p : s.positions) {
      char line[128];
      std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", p[0], p[1], p[2]);
      text += line;
    }
    for (const auto& f : s.faces) {
      text += "f";
      for (int i : f) text += " " + std::to_string(base + i);
      text += "\n";
    }
    base += int(s.positions.size());
  }
  return text;
}

SceneSettings settingsFor(const std::string& name) {
  SceneSettings s = test::tinySettings(96);
  s.name = name;
  s.eye = Vec3(0.8, 1.1, 2.2);
  s.near = 0.5;
  s.shading = ShadingMode::Phong;
  return s;
}

Scene loaded(const SceneSettings& settings) {
  Warnings warnings;
  Scene scene = loadScene(settings, warnings);
  EXPECT_TRUE(warnings.empty());
  return scene;
}

// Objects at their own coordinates, one file used twice: the same frame, bit for bit, as one
// OBJ holding the objects' faces in list order.
TEST(SceneObjects, ObjectsInPlaceDrawAsTheirMergedObj) {
  const test::TempDir dir;
  const Shape a = box(Vec3(-1, -1, -1), 1.25), b = pyramid(Vec3(0, -0.75, -0.5), 1.0);
  const std::string fileA = dir.write("a.obj", objOf({a})), fileB = dir.write("b.obj", objOf({b}));
  SceneSettings objects = settingsFor("objects");
  objects.objects = {SceneObject{fileA}, SceneObject{fileB}, SceneObject{fileA}};
  objects.modelPath = fileA;
  const Scene scene = loaded(objects);
  ASSERT_EQ(scene.models.size(), 2u) << "a file used twice is read once";
  ASSERT_EQ(scene.mesh->faceCount(), a.faces.size() + b.faces.size());
  ASSERT_EQ(scene.faceCount(), 2 * a.faces.size() + b.faces.size());
  EXPECT_EQ(scene.instances[2].firstId, uint32_t(a.faces.size() + b.faces.size()));

  SceneSettings merged = settingsFor("merged");
  merged.modelPath = dir.write("merged.obj", objOf({a, b, a}));
  const Scene reference = loaded(merged);
  for (const std::string& algorithm : algorithmNames()) {
    const test::Rendered r = test::render(scene, algorithm);
    ASSERT_GT(test::coveredSamples(r.buffer), 500u);
    test::expectSameFrame(test::render(reference, algorithm), r, algorithm);
  }
}

// Placed objects (translated, rotated, scaled): every algorithm draws what the z-buffer draws,
// bit for bit, and the ids match the merged OBJ of the placed vertices (computed here) but where
// the two roundings of a vertex put an edge on the other side of a sample.
TEST(SceneObjects, PlacedObjectsMatchTheirPlacedVertices) {
  const test::TempDir dir;
  const Shape a = box(Vec3(-0.5, -0.5, -0.5), 1.0), b = pyramid(Vec3(-0.5, 0, -0.5), 1.0);
  const std::string fileA = dir.write("a.ply",
                                      "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\n"
                                      "property float y\nproperty float z\nelement face 6\n"
                                      "property list uchar int vertex_indices\nend_header\n"
                                      "-0.5 -0.5 -0.5\n0.5 -0.5 -0.5\n-0.5 0.5 -0.5\n0.5 0.5 -0.5\n"
                                      "-0.5 -0.5 0.5\n0.5 -0.5 0.5\n-0.5 0.5 0.5\n0.5 0.5 0.5\n"
                                      "4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n"
                                      "4 1 3 7 5\n");
  const std::string fileB = dir.write("b.obj", objOf({b}));
  SceneSettings objects = settingsFor("objects");
  SceneObject first{fileA}, second{fileB}, third{fileA};
  first.translate = Vec3(-1.0, 0.0, -0.5);
  first.angle = 30.0;
  first.axis = Vec3(0, 1, 0);
  second.translate = Vec3(0.5, -0.5, 0.25);
  second.scale = Vec3(1.5, 1.0, 0.75);
  third.translate = Vec3(0.75, 0.5, -1.5);
  third.angle = -20.0;
  third.axis = Vec3(1, 0, 1);
  third.scale = Vec3(0.5, 0.5, 0.5);
  objects.objects = {first, second, third};
  objects.modelPath = fileA;
  const Scene scene = loaded(objects);

  // The merged OBJ: each object's vertices through its matrix, computed here.
  std::vector<Shape> placed;
  const Shape* shapes[3] = {&a, &b, &a};
  for (size_t o = 0; o < 3; ++o) {
    const SceneObject& object = objects.objects[o];
    const Mat4 m = translation(object.translate) * rotation(object.angle, object.axis) *
                   Mat4(object.scale[0], 0, 0, 0, 0, object.scale[1], 0, 0, 0, 0, object.scale[2],
                        0, 0, 0, 0, 1);
    Shape s = *shapes[o];
    for (Vec3& p : s.positions) p = transformPoint(m, p);
    placed.push_back(s);
  }
  SceneSettings merged = settingsFor("merged");
  merged.modelPath = dir.write("merged.obj", objOf(placed));
  const Scene reference = loaded(merged);
  // The objects' sphere (around their boxes' corners) holds every placed vertex.
  for (const Shape& shape : placed) {
    for (const Vec3& p : shape.positions)
      EXPECT_LE(cv::norm(p - scene.boundsCentre), scene.boundsRadius * (1 + 1e-12));
  }
  EXPECT_LE(scene.boundsRadius, 2.0 * reference.boundsRadius);

  const test::Rendered z = test::render(scene, "zbuffer");
  const test::Rendered mergedZ = test::render(reference, "zbuffer");
  size_t samples = 0, sameId = 0;
  for (int y = 0; y < z.buffer.height(); ++y) {
    for (int x = 0; x < z.buffer.width(); ++x) {
      const uint32_t id = keyFaceId(z.buffer.row(y)[x]);
      samples += id != kBackgroundId;
      sameId += id != kBackgroundId && id == keyFaceId(mergedZ.buffer.row(y)[x]);
    }
  }
  ASSERT_GT(samples, 500u);
  EXPECT_GE(double(sameId), 0.98 * double(samples));
  for (const std::string& algorithm : algorithmNames())
    test::expectSameFrame(z, test::render(scene, algorithm), algorithm);
}

// An object's color is its faces' base color: the same frame as its file with that Kd.
TEST(SceneObjects, AnObjectsColorIsItsBaseColor) {
  const test::TempDir dir;
  const Shape a = box(Vec3(-1, -1, -1), 1.5);
  dir.write("m.mtl", "newmtl c\nKd 0.25 0.5 0.75\n");
  const std::string plain = dir.write("a.obj", objOf({a}));
  const std::string colored = dir.write("c.obj", "mtllib m.mtl\nusemtl c\n" + objOf({a}));
  SceneSettings objects = settingsFor("objects");
  SceneObject object{plain};
  object.color = cv::Vec3d(0.25, 0.5, 0.75);
  objects.objects = {object};
  objects.modelPath = plain;
  SceneSettings reference = settingsFor("reference");
  reference.modelPath = colored;
  test::expectSameFrame(test::render(loaded(reference), "zbuffer"),
                        test::render(loaded(objects), "zbuffer"), "color");
}

TEST(SceneObjects, SettingsReadObjectsAndRefuseBadOnes) {
  const test::TempDir dir;
  Warnings warnings;
  const SettingsFile file = parseSettings(
      R"({"s": {"objects": [{"path": "a.obj"}, {"path": "b.ply", "translate": [1, 2, 3],
          "rotate": [90, [0, 1, 0]], "scale": 2, "color": [0.5, 0.25, 1], "texture": "t.png"}],
          "fit": true}})",
      dir.file("settings.json"), warnings);
  const SceneSettings& s = file.scenes.at("s");
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(s.objects[1].path, dir.file("b.ply"));
  EXPECT_EQ(s.objects[1].translate, cv::Vec3d(1, 2, 3));
  EXPECT_EQ(s.objects[1].angle, 90.0);
  EXPECT_EQ(s.objects[1].scale, cv::Vec3d(2, 2, 2));
  EXPECT_EQ(*s.objects[1].color, cv::Vec3d(0.5, 0.25, 1));
  EXPECT_EQ(*s.objects[1].texture, dir.file("t.png"));
  EXPECT_TRUE(warnings.empty());

  const std::pair<const char*, const char*> bad[] = {
      {R"({"s": {"objects": []}})", "key 'objects': expected a non-empty array"},
      {R"({"s": {"objects": [{"translate": [0, 0, 0]}]}})", "key 'objects[0].path': missing"},
      {R"({"s": {"objects": [{"path": "a.obj", "scale": 0}]}})", "key 'objects[0].scale'"},
      {R"({"s": {"objects": [{"path": "a.obj", "rotate": 90}]}})",
       "key 'objects[0].rotate': expected [angle, [x, y, z]]"},
      {R"({"s": {"objects": [{"path": "a.obj", "color": [2, 0, 0]}]}})", "key 'objects[0].color'"},
      {R"({"s": {"path": "a.obj", "objects": [{"path": "a.obj"}]}})", "not both"}};
  for (const auto& [text, message] : bad) {
    try {
      Warnings w;
      parseSettings(text, dir.file("settings.json"), w);
      ADD_FAILURE() << text;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
}

// Several model files on the command line: one scene whose ids count across the files.
TEST(SceneObjects, SeveralFilesOnTheCommandLineAreOneScene) {
  const test::TempDir dir;
  const Shape a = box(Vec3(-1, -1, -1), 1.25), b = pyramid(Vec3(0, -0.75, -0.5), 1.0);
  const std::string fileA = dir.write("a.obj", objOf({a})), fileB = dir.write("b.obj", objOf({b}));
  const std::string merged = dir.write("ab.obj", objOf({a, b}));
  const std::vector<std::string> size = {"--width", "64", "--height", "64"};
  std::vector<std::string> two = {
      fileA, fileB, "--ids", dir.file("two.png"), "-o", dir.file("c2.png")};
  std::vector<std::string> one = {merged, "--ids", dir.file("one.png"), "-o", dir.file("c1.png")};
  two.insert(two.end(), size.begin(), size.end());
  one.insert(one.end(), size.begin(), size.end());
  const test::RunResult r2 = test::runZrender(two), r1 = test::runZrender(one);
  ASSERT_EQ(r2.status, 0) << r2.err;
  ASSERT_EQ(r1.status, 0) << r1.err;
  EXPECT_EQ(test::readFile(dir.file("two.png")), test::readFile(dir.file("one.png")));
  EXPECT_EQ(test::readFile(dir.file("c2.png")), test::readFile(dir.file("c1.png")));
}

}  // namespace
}  // namespace zrender

namespace zrender {
namespace {

// An object's own texture: its faces draw as when that texture is the whole scene's; an object
// without one keeps its faces' own (here none: its material's Kd).
TEST(SceneObjects, AnObjectsTextureIsItsFacesTexture) {
  const test::TempDir dir;
  cv::Mat texture(2, 2, CV_8UC3);
  texture.at<cv::Vec3b>(0, 0) = cv::Vec3b(200, 40, 100);
  texture.at<cv::Vec3b>(0, 1) = cv::Vec3b(10, 220, 60);
  texture.at<cv::Vec3b>(1, 0) = cv::Vec3b(90, 80, 240);
  texture.at<cv::Vec3b>(1, 1) = cv::Vec3b(60, 160, 20);
  ASSERT_TRUE(test::imwrite(dir.file("t.png"), texture));
  const std::string square =
      dir.write("square.obj",
                "v -1.5 -1 0\nv -0.1 -1 0\nv -0.1 1 0\nv -1.5 1 0\nvt 0 0\nvt 1 0\nvt 1 1\n"
                "vt 0 1\nf 1/1 2/2 3/3 4/4\n");
  SceneSettings settings = test::tinySettings(40);
  settings.name = "objects";
  settings.shading = ShadingMode::Texture;
  SceneObject textured(square), plain(square);
  textured.texture = std::filesystem::path(dir.file("t.png"));
  plain.translate = Vec3(1.6, 0, 0);
  settings.objects = {textured, plain};
  settings.modelPath = square;
  Warnings warnings;
  const Scene scene = loadScene(settings, warnings);
  ASSERT_EQ(scene.objectTextures.size(), 1u);
  const test::Rendered r = test::render(scene, "zbuffer");

  SceneSettings alone = test::tinySettings(40);
  alone.modelPath = square;
  alone.shading = ShadingMode::Texture;
  alone.texture = std::filesystem::path(dir.file("t.png"));
  const test::Rendered a = test::render(loadScene(alone, warnings), "zbuffer");
  size_t covered = 0;
  for (int y = 0; y < 40; ++y) {
    for (int x = 0; x < 40; ++x) {
      if (keyFaceId(r.buffer.row(y)[x]) != 0) continue;
      ++covered;
      ASSERT_EQ(r.color.at<cv::Vec3b>(y, x), a.color.at<cv::Vec3b>(y, x)) << x << ", " << y;
    }
  }
  EXPECT_GT(covered, 100u);
}

}  // namespace
}  // namespace zrender

namespace zrender {
namespace {

// A grid repeats the whole list of objects: cell after cell, the objects in list order in each,
// face ids counting on; the same frame as the merged OBJ of the cells' objects.
TEST(SceneObjects, AGridRepeatsTheWholeList) {
  const test::TempDir dir;
  const Shape a = box(Vec3(-0.5, -0.5, -0.5), 0.75), b = pyramid(Vec3(0, -0.5, -0.25), 0.5);
  const std::string fileA = dir.write("a.obj", objOf({a})), fileB = dir.write("b.obj", objOf({b}));
  SceneSettings objects = settingsFor("objects");
  objects.eye = Vec3(0.5, 1.0, 4.0);
  objects.objects = {SceneObject(fileA), SceneObject(fileB)};
  objects.modelPath = fileA;
  objects.grid = Grid{{2, 1, 1}, {2.0, 0.0, 0.0}};
  const Scene scene = loaded(objects);
  ASSERT_EQ(scene.instanceCount(), 4u);
  EXPECT_EQ(scene.instances[2].firstId, uint32_t(a.faces.size() + b.faces.size()));
  // The cells at x offsets -1 and +1: exact in double, as the grid's translation is.
  std::vector<Shape> cells;
  for (double dx : {-1.0, 1.0}) {
    for (Shape s : {a, b}) {
      for (Vec3& p : s.positions) p[0] += dx;
      cells.push_back(s);
    }
  }
  SceneSettings merged = settingsFor("merged");
  merged.eye = objects.eye;
  merged.modelPath = dir.write("merged.obj", objOf(cells));
  const Scene reference = loaded(merged);
  for (const std::string& algorithm : algorithmNames())
    test::expectSameFrame(test::render(reference, algorithm), test::render(scene, algorithm),
                          algorithm);
}

}  // namespace
}  // namespace zrender
