// Every algorithm against the z-buffer: bit-identical keys (depth + id) and colors on the
// reference models, the crowd scene, quads, concave polygons, random soups, off-screen and
// near-plane geometry, every shading mode, culling off and MSAA 4, and the render fuzz corpus.
// `hierarchical` and `octree` are compared as a pair, as are `scanline` and `interval`.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "../fuzz/RenderCase.hpp"
#include "support/AlgorithmAgreement.hpp"
#include "support/TestMeshes.hpp"
#include "support/TestSupport.hpp"
#include "zrender/io/obj/ObjLoader.hpp"
#include "zrender/scene/ShadingMode.hpp"

namespace zrender {
namespace {

namespace fs = std::filesystem;
using test::addTiltedFloor;
using test::combOutline;
using test::Compared;
using test::expectSameAsZBuffer;
using test::intervalCounter;
using test::planarPolygon;
using test::PolygonSoup;
using test::referenceScene;

// ---------------------------------------------------------------------------------------------
// Reference models at a reduced size, with options.

TEST(AlgorithmsAgree, HierarchicalAndOctreeOnReferenceModels) {
  for (const std::string name : {"bunny", "spot", "teapot"}) {
    SceneSettings s;
    auto mesh = referenceScene(name, 360, s);
    if (!mesh) GTEST_SKIP() << name << " not linked under models/";
    const Compared c = expectSameAsZBuffer(mesh, s, test::kPyramidAlgorithms, name);
    EXPECT_GT(c.covered, 1000u) << name;
  }
}

TEST(AlgorithmsAgree, HierarchicalAndOctreeOnBunnyWithMsaaAndNoCull) {
  SceneSettings s;
  auto mesh = referenceScene("bunny", 240, s);
  if (!mesh) GTEST_SKIP() << "bunny not linked under models/";
  s.msaa = 4;
  expectSameAsZBuffer(mesh, s, test::kPyramidAlgorithms, "msaa 4");
  s.cull = false;
  expectSameAsZBuffer(mesh, s, test::kPyramidAlgorithms, "msaa 4, no cull");
  s.msaa = 1;
  expectSameAsZBuffer(mesh, s, test::kPyramidAlgorithms, "no cull");
}

TEST(AlgorithmsAgree, HierarchicalAndOctreeInEveryShadingMode) {
  SceneSettings s;
  auto mesh = referenceScene("spot", 200, s);
  if (!mesh) GTEST_SKIP() << "spot not linked under models/";
  for (const std::string& mode : shadingModeNames()) {
    s.shading = *parseShadingMode(mode);
    expectSameAsZBuffer(mesh, s, test::kPyramidAlgorithms, "shading " + mode);
  }
}

TEST(AlgorithmsAgree, HierarchicalAndOctreeOnASmallCrowd) {
  SceneSettings s;
  auto mesh = referenceScene("crowd", 200, s);
  if (!mesh) GTEST_SKIP() << "bunny not linked under models/";
  const Compared c = expectSameAsZBuffer(mesh, s, test::kPyramidAlgorithms, "crowd 200");
  EXPECT_GT(c.covered, 5000u);
  const RenderStats& octree = c.stats[1];
  EXPECT_GT(octree.octreeNodesVisited, 0u);
  EXPECT_GT(octree.octreeNodesCulled, 0u);
  EXPECT_GT(octree.trianglesHzbCulled, 0u);
  EXPECT_GT(c.stats[0].trianglesHzbCulled, 0u);
  // The octree transforms only what its visible nodes hold.
  EXPECT_LT(octree.trianglesRasterized + octree.trianglesHzbCulled,
            c.stats[0].trianglesRasterized + c.stats[0].trianglesHzbCulled);
}

TEST(AlgorithmsAgree, HierarchicalAndOctreeOnCrowdVariants) {
  // A smaller grid for the option variants: MSAA 4, no culling, another view from the side.
  SceneSettings s;
  auto mesh = referenceScene("crowd", 150, s);
  if (!mesh) GTEST_SKIP() << "bunny not linked under models/";
  s.grid->count = {4, 1, 4};
  s.msaa = 4;
  expectSameAsZBuffer(mesh, s, test::kPyramidAlgorithms, "crowd 4x4 msaa 4");
  s.msaa = 1;
  s.cull = false;
  expectSameAsZBuffer(mesh, s, test::kPyramidAlgorithms, "crowd 4x4 no cull");
  s.cull = true;
  s.eye = Vec3(1.2, 0.5, 0.3);
  s.target = Vec3(0.0, 0.1, 0.0);
  expectSameAsZBuffer(mesh, s, test::kPyramidAlgorithms, "crowd 4x4 side");
}

void expectModelSame(const std::string& name, int size) {
  auto mesh = test::referenceModel(name);
  if (!mesh) GTEST_SKIP() << "model " << name << " is not linked under models/";
  SceneSettings s = test::projectScene(name);
  s.width = s.height = size;
  EXPECT_GT(expectSameAsZBuffer(mesh, s, test::kScanlineAlgorithms, name).covered,
            size_t(size) * size / 20);
}

TEST(AlgorithmsAgree, ScanlineAndIntervalOnBunny) {
  expectModelSame("bunny", 300);
}
TEST(AlgorithmsAgree, ScanlineAndIntervalOnSpot) {
  expectModelSame("spot", 300);
}
TEST(AlgorithmsAgree, ScanlineAndIntervalOnTeapot) {
  expectModelSame("teapot", 300);
}

TEST(AlgorithmsAgree, ScanlineAndIntervalOnBunnyNoCullNonSquare) {
  auto mesh = test::referenceModel("bunny");
  if (!mesh) GTEST_SKIP() << "bunny is not linked under models/";
  SceneSettings s = test::projectScene("bunny");
  s.width = 320;
  s.height = 240;
  s.aspect = 0.0;
  s.cull = false;
  s.shading = ShadingMode::Id;
  EXPECT_GT(
      expectSameAsZBuffer(mesh, s, test::kScanlineAlgorithms, "bunny --no-cull 320x240").covered,
      10000u);
}

// The eye close to the bunny: part of it is cut by the near plane, part is off screen, and
// the clipped faces project to huge coordinates.
TEST(AlgorithmsAgree, ScanlineAndIntervalOnBunnyNearPlaneAndHalfOutside) {
  auto mesh = test::referenceModel("bunny");
  if (!mesh) GTEST_SKIP() << "bunny is not linked under models/";
  SceneSettings s = test::projectScene("bunny");
  s.width = s.height = 240;
  s.shading = ShadingMode::Depth;
  struct View {
    cv::Vec3d eye, target;
    double near;
    bool cull, nearPlaneCuts, partlyEmpty;
  };
  const View views[] = {
      // near plane through the body, bunny off the top and right borders
      {{0.06, 0.12, 0.10}, {-0.08, 0.10, -0.01}, 0.07, true, true, true},
      // eye inside the bunny, everything around it drawn
      {{0.02, 0.11, 0.03}, {-0.10, 0.10, -0.02}, 0.005, false, true, false},
      // bunny cut by the bottom and right borders
      {{-0.20, 0.10, 0.25}, {0.05, 0.12, -0.01}, 0.1, true, false, true},
  };
  for (const View& v : views) {
    s.eye = v.eye;
    s.target = v.target;
    s.near = v.near;
    s.cull = v.cull;
    Warnings warnings;
    const Scene scene = makeScene(s, mesh);
    // Check the scenario: some vertices in front of the near plane, some behind it.
    const Camera camera = makeCamera(scene);
    double nearest = 1e300, farthest = -1e300;
    for (const Vec3& p : mesh->positions) {
      const Vec4 q = camera.view * Vec4(p[0], p[1], p[2], 1.0);
      nearest = std::min(nearest, -q[2]);
      farthest = std::max(farthest, -q[2]);
    }
    if (v.nearPlaneCuts) {
      EXPECT_LT(nearest, v.near);
      EXPECT_GT(farthest, v.near);
    }
    const size_t covered =
        expectSameAsZBuffer(scene, test::kScanlineAlgorithms, "bunny close up").covered;
    EXPECT_GT(covered, 1000u);
    if (v.partlyEmpty) {
      EXPECT_LT(covered, size_t(s.width) * s.height);
    }
  }
}

TEST(AlgorithmsAgree, ScanlineAndIntervalInEveryShadingMode) {
  auto mesh = test::referenceModel("spot");
  if (!mesh) GTEST_SKIP() << "spot is not linked under models/";
  SceneSettings s = test::projectScene("spot");
  s.width = s.height = 128;
  for (const std::string& name : shadingModeNames()) {
    s.shading = *parseShadingMode(name);
    expectSameAsZBuffer(mesh, s, test::kScanlineAlgorithms, "spot shading " + name);
  }
  s.msaa = 4;
  s.shading = ShadingMode::Texture;
  EXPECT_GT(expectSameAsZBuffer(mesh, s, test::kScanlineAlgorithms, "spot msaa 4 texture").covered,
            2000u);
}

TEST(AlgorithmsAgree, ScanlineAndIntervalOnTeapotWithMsaa4AndNoCull) {
  auto mesh = test::referenceModel("teapot");
  if (!mesh) GTEST_SKIP() << "teapot is not linked under models/";
  SceneSettings s = test::projectScene("teapot");
  s.width = s.height = 160;
  s.msaa = 4;
  s.cull = false;
  s.shading = ShadingMode::Phong;
  EXPECT_GT(
      expectSameAsZBuffer(mesh, s, test::kScanlineAlgorithms, "teapot msaa 4 no cull").covered,
      2000u);
}

// ---------------------------------------------------------------------------------------------
// Quads and concave polygons (drawn natively by the scan-line algorithms), random soups with
// interpenetrating triangles (crossing depths inside spans) and exact coplanar duplicates (ties
// that the smaller id must win), near-plane and off-screen geometry.

TEST(AlgorithmsAgree, HierarchicalAndOctreeOnQuadsAndAConcavePolygon) {
  // Overlapping quads at different depths and tilts, and a concave (arrow-shaped) polygon that
  // pierces them.
  std::vector<Vec3> p = {{-1.5, -1.5, -0.5}, {1.0, -1.5, -0.3}, {1.0, 1.0, -0.1}, {-1.5, 1.0, -0.3},
                         {-0.5, -0.5, 0.2},  {1.8, -0.5, -0.6}, {1.8, 1.8, -0.6}, {-0.5, 1.8, 0.2},
                         {-1.8, -1.0, 0.0},  {0.0, -1.6, 0.0},  {1.6, -1.0, 0.0}, {0.5, -0.8, -0.9},
                         {1.4, 0.8, 0.0},    {0.0, 0.1, 0.9},   {-1.4, 0.8, -0.4}};
  std::vector<std::vector<int>> f = {{0, 1, 2, 3}, {4, 5, 6, 7}, {8, 9, 10, 11, 12, 13, 14}};
  for (bool cull : {true, false}) {
    SceneSettings s = test::tinySettings(97);
    s.cull = cull;
    const Compared c =
        expectSameAsZBuffer(test::makeMesh(p, f), s, test::kPyramidAlgorithms, "quads");
    EXPECT_GT(c.covered, 2000u);
  }
}

TEST(AlgorithmsAgree, HierarchicalAndOctreeOnRandomSoupsWithCoplanarDuplicates) {
  for (unsigned seed : {1u, 2u, 3u, 4u, 5u}) {
    SceneSettings s = test::tinySettings(80 + int(seed) * 7);
    s.cull = false;
    s.msaa = seed % 2 ? 1 : 4;
    const Compared c =
        expectSameAsZBuffer(test::randomSoup(seed, 400, true), s, test::kPyramidAlgorithms,
                            "soup " + std::to_string(seed));
    EXPECT_GT(c.covered, 1000u);
  }
}

TEST(AlgorithmsAgree, HierarchicalAndOctreeAcrossTheNearPlaneAndOffScreen) {
  // A tilted floor that runs from far away to behind the eye and past the image's sides, with
  // posts standing on it; and the bunny seen from inside itself.
  std::vector<Vec3> p;
  std::vector<std::vector<int>> f;
  addTiltedFloor(24, false, p, f);
  for (int k = 0; k < 6; ++k) {
    const int b = int(p.size());
    const double x = -2.5 + k, z = -3.0 + 0.8 * k;
    p.insert(p.end(), {{x, -0.7, z}, {x + 0.4, -0.7, z}, {x + 0.4, 1.5, z}, {x, 1.5, z}});
    f.push_back({b, b + 1, b + 2, b + 3});
  }
  for (bool cull : {true, false}) {
    SceneSettings s = test::tinySettings(90);
    s.cull = cull;
    s.eye = Vec3(0.3, 0.2, 1.0);
    const Compared c =
        expectSameAsZBuffer(test::makeMesh(p, f), s, test::kPyramidAlgorithms, "floor");
    EXPECT_GT(c.covered, 1000u);
  }

  SceneSettings s;
  auto mesh = referenceScene("bunny", 200, s);
  if (!mesh) GTEST_SKIP() << "bunny not linked under models/";
  s.eye = Vec3(-0.02, 0.11, 0.02);
  s.target = Vec3(0.1, 0.12, -0.1);
  s.fovy = 80.0;
  s.near = 0.005;
  s.cull = false;
  const Compared c = expectSameAsZBuffer(mesh, s, test::kPyramidAlgorithms, "inside the bunny");
  EXPECT_GT(c.covered, 1000u);
}

std::vector<std::pair<double, double>> starOutline(int points, double outer, double inner) {
  std::vector<std::pair<double, double>> o;
  for (int k = 0; k < 2 * points; ++k) {
    const double r = k % 2 ? inner : outer, a = M_PI * k / points;
    o.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return o;
}

TEST(AlgorithmsAgree, ScanlineAndIntervalOnQuadsAndParallelograms) {
  PolygonSoup soup;
  // A tilted 6 x 6 grid of quads sharing edges (no gaps, no double cover along them).
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 6; ++i) {
      const double x = -1.5 + 0.5 * i, y = -1.5 + 0.5 * j;
      soup.add(planarPolygon({{x, y}, {x + 0.5, y}, {x + 0.5, y + 0.5}, {x, y + 0.5}}, 0.3, 0, 0,
                             0.2, -0.1, 0.0));
    }
  // Random parallelograms c +- u +- v crossing the grid and each other.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> r(-1.0, 1.0);
  for (int k = 0; k < 40; ++k) {
    const Vec3 c(r(rng), r(rng), 0.5 * r(rng)), u(0.6 * r(rng), 0.6 * r(rng), 0.6 * r(rng)),
        v(0.6 * r(rng), 0.6 * r(rng), 0.6 * r(rng));
    soup.add({c - u - v, c + u - v, c + u + v, c - u + v});
  }
  SceneSettings s = test::tinySettings(160);
  s.cull = false;
  s.shading = ShadingMode::Random;
  EXPECT_GT(expectSameAsZBuffer(test::makeMesh(soup.positions, soup.faces), s,
                                test::kScanlineAlgorithms, "quads")
                .covered,
            8000u);
}

TEST(AlgorithmsAgree, ScanlineAndIntervalOnConcavePolygons) {
  PolygonSoup soup;
  // L-shape, comb (10 crossings per row through its teeth), stars, in tilted planes that cut
  // through one another.
  soup.add(planarPolygon({{-1, -1}, {1, -1}, {1, -0.4}, {-0.4, -0.4}, {-0.4, 1}, {-1, 1}}, 0.2,
                         -0.3, 0.2, 0.3, 0.1, 0.0));
  soup.add(planarPolygon(combOutline(5, 1.2, 0.8), -0.15, 0.2, 0.1, -0.25, 0.2, 0.05));
  soup.add(planarPolygon(starOutline(7, 1.3, 0.5), 0.05, 0.4, -0.3, 0.1, -0.3, -0.05));
  soup.add(planarPolygon(starOutline(5, 0.9, 0.3), 0.0, -0.8, 0.9, 0.0, 0.0, 0.3));
  soup.add(planarPolygon(combOutline(3, 0.7, 0.5), 1.7, 1.0, 0.8, 0.0, 0.0, 0.2));
  for (const int size : {97, 200}) {
    SceneSettings s = test::tinySettings(size);
    s.cull = false;
    s.shading = ShadingMode::Id;
    EXPECT_GT(expectSameAsZBuffer(test::makeMesh(soup.positions, soup.faces), s,
                                  test::kScanlineAlgorithms, "concave polygons")
                  .covered,
              size_t(size) * size / 10);
    s.msaa = 4;
    EXPECT_GT(expectSameAsZBuffer(test::makeMesh(soup.positions, soup.faces), s,
                                  test::kScanlineAlgorithms, "concave polygons, msaa 4")
                  .covered,
              size_t(size) * size / 10);
  }
}

TEST(AlgorithmsAgree, ScanlineAndIntervalOnRandomSoups) {
  uint64_t split = 0;
  for (unsigned seed = 1; seed <= 12; ++seed) {
    SceneSettings s = test::tinySettings(seed % 2 ? 180 : 131);
    s.width += int(seed) * 7;  // non-square too
    s.cull = false;
    s.shading = ShadingMode::Id;
    const auto soup = test::randomSoup(seed, 300, true);
    EXPECT_GT(
        expectSameAsZBuffer(soup, s, test::kScanlineAlgorithms, "soup seed " + std::to_string(seed))
            .covered,
        1000u);
    split += intervalCounter(soup, s, "spans_split");
  }
  EXPECT_GT(split, 100u);  // depths crossing inside spans were really met
}

// Triangles in nearly one plane, offsets from 1e-3 down to 1e-8: ties and ulp-sized crossings.
TEST(AlgorithmsAgree, ScanlineAndIntervalOnRandomNearlyCoplanarSoups) {
  uint64_t oneByOne = 0;
  for (unsigned seed = 1; seed <= 40; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> coord(-1.8, 1.8), unit(-1.0, 1.0);
    const double offset = std::pow(10.0, -3.0 - double(seed % 6));
    const double px = 0.3 * unit(rng), py = 0.3 * unit(rng);
    PolygonSoup soup;
    for (int t = 0; t < 40; ++t) {
      std::vector<Vec3> corners;
      for (int i = 0; i < 3; ++i) {
        const double x = coord(rng), y = coord(rng);
        corners.emplace_back(x, y, px * x + py * y + offset * unit(rng));
      }
      soup.add(corners);
    }
    SceneSettings s = test::tinySettings(100 + int(seed % 37));
    s.cull = false;
    s.near = 0.5 + (seed % 5) * 0.3;
    s.shading = ShadingMode::Id;
    const auto mesh = test::makeMesh(soup.positions, soup.faces);
    EXPECT_GT(expectSameAsZBuffer(mesh, s, test::kScanlineAlgorithms,
                                  "near coplanar seed " + std::to_string(seed))
                  .covered,
              1000u);
    oneByOne += intervalCounter(mesh, s, "samples_one_by_one");
  }
  EXPECT_GT(oneByOne, 1000u);  // the end values could not decide there: exact keys did
}

TEST(AlgorithmsAgree, ScanlineAndIntervalOnARandomSoupWithMsaa4) {
  SceneSettings s = test::tinySettings(120);
  s.cull = false;
  s.msaa = 4;
  s.shading = ShadingMode::Depth;
  EXPECT_GT(expectSameAsZBuffer(test::randomSoup(9, 200, true), s, test::kScanlineAlgorithms,
                                "soup msaa 4")
                .covered,
            1000u);
}

// Nearly coplanar layers: depths within a few float ulps over whole spans, where the end values
// cannot prove the order and samples must be decided one by one.
TEST(AlgorithmsAgree, ScanlineAndIntervalOnNearlyCoplanarLayers) {
  PolygonSoup soup;
  for (int k = 0; k < 6; ++k) {
    const double eps = 1e-7 * k;
    soup.add({{-1.5, -1.2, eps}, {1.4, -1.5, -eps}, {0.1, 1.5, 2 * eps}});
    soup.add({{-1.3, 1.4, -eps}, {-1.2, -1.5, eps}, {1.5, 0.3, 0.0}});
  }
  SceneSettings s = test::tinySettings(150);
  s.cull = false;
  s.shading = ShadingMode::Id;
  const auto mesh = test::makeMesh(soup.positions, soup.faces);
  EXPECT_GT(expectSameAsZBuffer(mesh, s, test::kScanlineAlgorithms, "near ties").covered, 5000u);
  EXPECT_GT(intervalCounter(mesh, s, "samples_one_by_one"), 100u);
}

// Faces far outside the image and across the near plane: huge snapped coordinates.
TEST(AlgorithmsAgree, ScanlineAndIntervalOnHugeAndOffscreenFaces) {
  PolygonSoup soup;
  soup.add({{-1000, -1000, -1}, {1000, -900, -1.2}, {0, 1000, -0.8}});  // covers everything
  soup.add({{-0.5, -0.5, 1.99}, {0.5, -0.4, 1.99}, {0, 0.5, -3}});      // crosses the near plane
  soup.add({{3, 3, 0}, {9, 3, 0}, {9, 9, 0}, {3, 9, 0}});               // off screen
  soup.add({{-50, 0.2, 0.5}, {50, 0.1, 0.4}, {0.2, 0.3, 0.5}});         // long sliver
  soup.add({{-1, -1.9, 0.2}, {1, -1.95, 0.2}, {0, -2.5, 0.2}});         // crosses the bottom
  // Just beyond the near plane (0.101 from the eye) and 1e4 to the sides: millions of pixels
  // off screen, cut by the guard band.
  soup.add({{-1e4, 0.3, 1.899}, {1e4, 0.35, 1.899}, {0.1, -0.2, 0.0}});
  soup.add({{0.3, -1e4, 1.8995}, {0.2, 1e4, 1.8995}, {-0.6, 0.4, 0.1}});
  SceneSettings s = test::tinySettings(90);
  s.cull = false;
  s.shading = ShadingMode::Id;
  EXPECT_EQ(expectSameAsZBuffer(test::makeMesh(soup.positions, soup.faces), s,
                                test::kScanlineAlgorithms, "huge")
                .covered,
            size_t(90 * 90));
}

// ---------------------------------------------------------------------------------------------
// Every input of the render fuzz target's corpus (seeds and the inputs it found): all
// algorithms agree, as the fuzz target checks.
TEST(AlgorithmsAgree, OnEveryInputOfTheRenderFuzzCorpus) {
  int files = 0;
  for (const auto& entry : fs::directory_iterator(ZRENDER_SOURCE_DIR "/fuzz/corpus/render")) {
    SCOPED_TRACE(entry.path().filename().string());
    const std::string bytes = test::readFile(entry.path().string());
    fuzz::RenderCase input;
    ASSERT_TRUE(fuzz::decodeRenderCase(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size(),
                                       input));
    Warnings warnings;
    std::shared_ptr<const Mesh> mesh;
    try {
      mesh = std::make_shared<const Mesh>(loadObjFromText(input.obj, "case.obj", warnings));
    } catch (const InputError&) {
      continue;
    }
    const Scene scene = makeScene(input.settings, mesh);
    EXPECT_EQ(fuzz::checkAlgorithmsAgree(scene, input.twice), "");
    ++files;
  }
  EXPECT_GT(files, 5);
}

}  // namespace
}  // namespace zrender
