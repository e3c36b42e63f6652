// SurfaceSetup: a frame's faces set up in a batch (in row order, on the threads) hold the same
// bits as each face set up alone when a row meets it: every plane, corner attribute and field,
// for every face of the model, front and back (the back ones turned to the eye), triangles and
// polygons, on one instance and on a grid. On a CPU with AVX2 the batch sets triangles up four
// at a time (SurfaceSetupAvx2.cpp), and a face set up alone goes through the scalar code: this
// is the test that the two give the same bits.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "support/TestSupport.hpp"
#include "zrender/base/Threads.hpp"
#include "zrender/io/SceneFiles.hpp"
#include "zrender/raster/FrameGeometry.hpp"
#include "zrender/scene/Camera.hpp"
#include "zrender/shading/SurfaceSetup.hpp"

namespace zrender {
namespace {

// The bytes of a float, so that -0 and 0, or two NaNs, count as different.
uint32_t bitsOf(float f) {
  uint32_t bits;
  std::memcpy(&bits, &f, sizeof bits);
  return bits;
}

void expectSameSurface(const FaceSurface& a, const SurfaceFan* aFans, const FaceSurface& b,
                       const SurfaceFan* bFans, const std::string& label) {
  ASSERT_EQ(a.fanCount, b.fanCount) << label;
  EXPECT_EQ(a.originX, b.originX) << label;
  EXPECT_EQ(a.originY, b.originY) << label;
  // Each SurfaceSetup frames its own copies of the scene's textures, in the same order.
  EXPECT_EQ(a.texture, b.texture) << label;
  for (int i = 0; i < 3; ++i) EXPECT_EQ(bitsOf(a.base[i]), bitsOf(b.base[i])) << label;
  for (uint32_t j = 0; j < a.fanCount; ++j) {
    const SurfaceFan& x = aFans[j];
    const SurfaceFan& y = bFans[j];
    EXPECT_EQ(x.degenerate, y.degenerate) << label;
    for (int k = 0; k < kSurfacePlanes; ++k) {
      ASSERT_EQ(bitsOf(x.a[k]), bitsOf(y.a[k])) << label << ", plane " << k;
      ASSERT_EQ(bitsOf(x.b[k]), bitsOf(y.b[k])) << label << ", plane " << k;
      ASSERT_EQ(bitsOf(x.c[k]), bitsOf(y.c[k])) << label << ", plane " << k;
    }
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 3; ++k)
        ASSERT_EQ(bitsOf(x.cornerNormal[i][k]), bitsOf(y.cornerNormal[i][k])) << label;
      for (int k = 0; k < 2; ++k)
        ASSERT_EQ(bitsOf(x.cornerUv[i][k]), bitsOf(y.cornerUv[i][k])) << label;
    }
  }
}

// Every face of the scene set up by setUpFaces() (its rows spread over the image) against the
// same face set up alone.
void expectBatchAgrees(const Scene& scene, int threads, const std::string& label) {
  const Camera camera = makeCamera(scene);
  std::vector<Mat4> modelView;
  for (uint32_t k = 0; k < scene.instanceCount(); ++k)
    modelView.push_back(camera.view * scene.modelMatrix(k));
  const int width = 640, height = 480;
  FrameGeometry geometry;
  for (uint32_t id = 0; id < scene.faceCount(); ++id) {
    ScreenFace face{};
    face.id = id;
    face.rows.first = uint16_t(id * 7919u % uint32_t(height));
    face.rows.last = face.rows.first;
    geometry.faces.push_back(face);
  }
  const FaceParts parts = {&geometry};
  SurfaceSetup batch(scene, scene.settings.shading), alone(scene, scene.settings.shading);
  batch.begin(modelView, camera, width, height);
  alone.begin(modelView, camera, width, height);
  const Threads pool(threads);
  ASSERT_TRUE(batch.setUpFaces(parts, SIZE_MAX, &pool)) << label;
  for (uint32_t id = 0; id < scene.faceCount(); ++id) {
    const FaceSurface& a = batch.surface(id);
    const FaceSurface& b = alone.surface(id);
    expectSameSurface(a, batch.fans(a), b, alone.fans(b), label + ", face " + std::to_string(id));
    if (testing::Test::HasFatalFailure()) return;
  }
}

TEST(SurfaceSetup, BatchHoldsTheBitsOfFacesSetUpAlone) {
  for (const ShadingMode mode : {ShadingMode::Normal, ShadingMode::Phong, ShadingMode::Texture}) {
    for (const std::string name : {"bunny", "spot", "teapot", "spot grid"}) {
      SceneSettings s = test::projectScene(name == "spot grid" ? "spot" : name);
      if (!std::filesystem::exists(s.modelPath)) continue;
      s.shading = mode;
      s.cull = name != "teapot";  // teapot: every face, back faces turned to the eye
      // Instances, each its own model-view.
      if (name == "spot grid") s.grid = Grid{{2, 1, 2}, {1.2, 0.0, 1.2}};
      Warnings warnings;
      const Scene scene = loadScene(s, warnings);
      for (const int threads : {1, 2})
        expectBatchAgrees(scene, threads,
                          name + " " + shadingModeName(mode) + " " + std::to_string(threads));
    }
  }
}

// Triangles that take the set-up's other branches, in every lane of a group of four: zero area
// (a corner repeated, three corners on a line), corners at and behind the eye (the planes'
// origin at the image's centre), faces seen from behind (turned to the eye), among random ones.
TEST(SurfaceSetup, BatchHoldsTheBitsOfOddTrianglesSetUpAlone) {
  std::vector<Vec3> positions;
  std::vector<std::vector<int>> faces;
  const auto add = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
    const int base = int(positions.size());
    positions.push_back(a);
    positions.push_back(b);
    positions.push_back(c);
    faces.push_back({base, base + 1, base + 2});
  };
  const Vec3 eye(0, 0, 2);  // tinySettings' eye
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(-1.0, 1.0);
  const auto random = [&] { return Vec3(coord(rng), coord(rng), coord(rng)); };
  for (int k = 0; k < 9; ++k) {  // each kind in several lanes of the groups
    const Vec3 a = random(), b = random(), c = random();
    add(a, a, b);                                  // a corner repeated
    add(a, 0.5 * (a + b), b);                      // on a line
    add(eye, a, b);                                // first corner at the eye
    add(a + Vec3(0, 0, 2.5), b, c);                // first corner behind the eye
    add(a + Vec3(0, 0, 3), b + Vec3(0, 0, 3), c);  // two behind
    add(c, b, a);                                  // wound the other way
    add(random(), random(), random());
  }
  SceneSettings settings = test::tinySettings(64);
  settings.cull = false;
  for (const ShadingMode mode : {ShadingMode::Normal, ShadingMode::Phong}) {
    settings.shading = mode;
    const Scene scene = makeScene(settings, test::makeMesh(positions, faces));
    for (const int threads : {1, 2})
      expectBatchAgrees(scene, threads,
                        "odd triangles " + shadingModeName(mode) + " " + std::to_string(threads));
  }
}

}  // namespace
}  // namespace zrender
