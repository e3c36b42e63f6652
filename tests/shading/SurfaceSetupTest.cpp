// SurfaceSetup: a frame's faces set up in a batch (in row order, on the threads) hold the same
// bits as each face set up alone when a row meets it: every plane, corner attribute and field,
// for every face of the model, front and back (the back ones turned to the eye), triangles and
// polygons, on one instance and on a grid.

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
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
  EXPECT_EQ(a.textured, b.textured) << label;
  // Each SurfaceSetup frames its own copy of a texture: its size, not its address.
  EXPECT_EQ(a.texels == nullptr, b.texels == nullptr) << label;
  EXPECT_EQ(a.textureWidth, b.textureWidth) << label;
  EXPECT_EQ(a.textureHeight, b.textureHeight) << label;
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

}  // namespace
}  // namespace zrender
