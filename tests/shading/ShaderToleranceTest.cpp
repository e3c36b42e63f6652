// The shader zrender runs (float, vector: SurfaceSetup and SurfaceKernel) against the
// double-precision reference it replaced (support/ReferenceShading): on the reference models,
// `shapes` (polygons), grids of instances and a scene seen without culling, in every shading
// mode, with and without MSAA 4, every channel of every pixel is within 1 (of 255) of the
// reference (docs/design.md, Faces, ids and shading, gives the tolerance and its reason).

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <opencv2/core.hpp>

#include "support/ReferenceShading.hpp"
#include "support/TestSupport.hpp"
#include "zrender/io/SceneFiles.hpp"
#include "zrender/render/Renderer.hpp"
#include "zrender/scene/ShadingMode.hpp"

namespace zrender {
namespace {

struct Difference {
  double largest = 0.0;  // of any channel of any pixel, 0..255
  int channelsOffByOne = 0;
  size_t coveredSamples = 0;
};

Difference compareWithReference(const Scene& scene) {
  Renderer renderer(scene, "zbuffer");
  const Camera camera = makeCamera(scene);
  renderer.renderFrame(camera);
  const cv::Mat reference =
      test::referenceImage(scene, camera, renderer.buffer(), renderer.sampleScale());
  cv::Mat difference;
  cv::absdiff(renderer.color(), reference, difference);
  Difference d;
  cv::minMaxLoc(difference.reshape(1), nullptr, &d.largest);
  d.channelsOffByOne = cv::countNonZero(difference.reshape(1) == 1);
  d.coveredSamples = test::coveredSamples(renderer.buffer());
  return d;
}

// Every shading mode with MSAA 1 and 4 on the scene of `settings`, loaded with its model and
// texture as zrender loads it.
void expectWithinOneInEveryMode(SceneSettings settings, const std::string& label,
                                size_t minimumCovered) {
  for (const std::string& mode : shadingModeNames()) {
    for (int msaa : {1, 4}) {
      settings.shading = *parseShadingMode(mode);
      settings.msaa = msaa;
      Warnings warnings;
      const Scene scene = loadScene(settings, warnings);
      const Difference d = compareWithReference(scene);
      const std::string where = label + ", " + mode + ", msaa " + std::to_string(msaa);
      EXPECT_LE(d.largest, 1.0) << where;
      EXPECT_GE(d.coveredSamples, minimumCovered) << where;
    }
  }
}

bool linked(const SceneSettings& settings) {
  return std::filesystem::exists(settings.modelPath);
}

TEST(ShaderTolerance, ReferenceModelsInEveryModeWithinOne) {
  for (const std::string name : {"bunny", "spot", "teapot"}) {
    SceneSettings s = test::projectScene(name);
    if (!linked(s)) GTEST_SKIP() << name << " is not linked under models/";
    s.width = s.height = 300;
    expectWithinOneInEveryMode(s, name, 10000);
  }
}

TEST(ShaderTolerance, SpotTexturedCloseUpWithinOne) {
  // Texels several pixels wide, where bilinear filtering shows, and the face planes far from
  // the image's corner.
  SceneSettings s = test::projectScene("spot");
  if (!linked(s)) GTEST_SKIP() << "spot is not linked under models/";
  s.width = s.height = 400;
  s.eye = Vec3(0.3, 0.5, 0.9);
  s.target = Vec3(0.0, 0.4, 0.0);
  for (const ShadingMode mode : {ShadingMode::Texture, ShadingMode::Phong}) {
    s.shading = mode;
    Warnings warnings;
    const Difference d = compareWithReference(loadScene(s, warnings));
    EXPECT_LE(d.largest, 1.0) << shadingModeName(mode);
    EXPECT_GT(d.coveredSamples, 40000u);
  }
}

TEST(ShaderTolerance, PolygonsOfShapesWithinOne) {
  SceneSettings s = test::projectScene("shapes");
  expectWithinOneInEveryMode(s, "shapes", 1000);
}

TEST(ShaderTolerance, GridsOfInstancesWithinOne) {
  SceneSettings crowd = test::projectScene("crowd");
  if (!linked(crowd)) GTEST_SKIP() << "bunny is not linked under models/";
  crowd.width = crowd.height = 200;
  expectWithinOneInEveryMode(crowd, "crowd", 5000);
  // A textured grid: each instance its own model-view.
  SceneSettings spots = test::projectScene("spot");
  spots.width = spots.height = 240;
  spots.grid = Grid{{2, 1, 2}, {1.2, 0.0, 1.2}};
  spots.fit = true;
  expectWithinOneInEveryMode(spots, "spot grid", 5000);
}

TEST(ShaderTolerance, BackFacesSeenWithoutCullingWithinOne) {
  // Back faces are lit from their own side (FaceSurface::flip).
  SceneSettings s = test::projectScene("teapot");
  if (!linked(s)) GTEST_SKIP() << "teapot is not linked under models/";
  s.width = s.height = 240;
  s.cull = false;
  expectWithinOneInEveryMode(s, "teapot, no cull", 5000);
}

}  // namespace
}  // namespace zrender
