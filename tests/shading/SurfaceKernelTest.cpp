// SurfaceKernel: the vector versions (AVX2, eight lanes, texels read by loads or by gathers)
// give the scalar reference's bits, on random faces (samples inside and outside the fan
// triangle, degenerate fans, infinite and NaN planes, every mode, a texture read across its
// wrap) and on the rows of real frames (background, polygons, runs of every length), as colors
// and as image bytes.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "support/TestSupport.hpp"
#include "zrender/base/CpuFeatures.hpp"
#include "zrender/io/SceneFiles.hpp"
#include "zrender/render/Renderer.hpp"
#include "zrender/shading/PixelRows.hpp"
#include "zrender/shading/SurfaceKernel.hpp"
#include "zrender/shading/SurfaceSetup.hpp"

namespace zrender {
namespace {

using RunFunction = void (*)(const SurfaceFrame&, const FaceSurface&, const SurfaceFan*, int, int,
                             int, uint32_t*);
using RowFunction = void (*)(SurfaceSetup&, const DepthKey*, int, int, uint32_t, uint32_t*);
using BgrRowFunction = void (*)(SurfaceSetup&, const DepthKey*, int, int, uint32_t, uint8_t*);

struct Version {
  std::string name;
  RunFunction run;
  RowFunction row;
  BgrRowFunction bgrRow;
};

// The vector versions this CPU runs.
std::vector<Version> vectorVersions() {
  std::vector<Version> versions;
  if (cpuHasAvx2()) {
    versions.push_back({"avx2", shadeSurfaceRunAvx2, shadeSurfaceRowAvx2, shadeSurfaceBgrRowAvx2});
    versions.push_back({"avx2 gathers", shadeSurfaceRunAvx2Gathers, shadeSurfaceRowAvx2Gathers,
                        shadeSurfaceBgrRowAvx2Gathers});
  }
  return versions;
}

// A random plane value: mostly ordinary, sometimes zero, huge, infinite or NaN.
float randomCoefficient(std::mt19937& rng, float scale) {
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  switch (std::uniform_int_distribution<int>(0, 40)(rng)) {
    case 0:
      return 0.0f;
    case 1:
      return std::numeric_limits<float>::infinity();
    case 2:
      return std::numeric_limits<float>::quiet_NaN();
    case 3:
      return 1e30f * u(rng);
    default:
      return scale * u(rng);
  }
}

// Plane k of the fan: a, b, c.
void setPlane(SurfaceFan& fan, int k, float a, float b, float c) {
  fan.a[k] = a, fan.b[k] = b, fan.c[k] = c;
}

void setRandomPlane(SurfaceFan& fan, int k, std::mt19937& rng) {
  setPlane(fan, k, randomCoefficient(rng, 0.05f), randomCoefficient(rng, 0.05f),
           randomCoefficient(rng, 1.0f));
}

TEST(SurfaceKernel, VectorRunsGiveTheScalarBitsOnRandomFaces) {
  const std::vector<Version> versions = vectorVersions();
  if (versions.empty()) GTEST_SKIP() << "this CPU has no AVX2";
  std::mt19937 rng(2026);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  // A 5 x 3 texture stored as SurfaceTexture says: framed by a copy of the last column and row
  // before the first and of the first after the last.
  const int tw = 5, th = 3;
  std::vector<uint32_t> texture(size_t(tw) * th);
  for (uint32_t& texel : texture) texel = rng() & 0xFFFFFFu;
  std::vector<uint32_t> texels(size_t(tw + 2) * (th + 2));
  for (int y = 0; y < th + 2; ++y)
    for (int x = 0; x < tw + 2; ++x)
      texels[size_t(y) * (tw + 2) + x] =
          texture[size_t((y + th - 1) % th) * tw + (x + tw - 1) % tw];
  const SurfaceTexture framed{texels.data(), tw, th};

  int outside = 0, inside = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    SurfaceFrame frame;
    const ShadingMode modes[3] = {ShadingMode::Normal, ShadingMode::Phong, ShadingMode::Texture};
    frame.mode = modes[trial % 3];
    frame.rayOriginX = -1.0f + 0.2f * unit(rng);
    frame.rayOriginY = 1.0f - 0.2f * unit(rng);
    frame.rayScaleX = 0.004f * unit(rng);
    frame.rayScaleY = 0.004f * unit(rng);
    frame.textures = &framed;
    FaceSurface face;
    face.originX = int(rng() % 500);
    face.originY = int(rng() % 500);
    face.fanCount = 1;
    face.texture = frame.mode == ShadingMode::Texture && rng() % 4 != 0 ? 0 : -1;
    for (float& c : face.base) c = 255.0f * unit(rng);
    SurfaceFan fan{};
    // Mostly a face whose weights are those of a triangle around the origin, so that runs
    // cross its edges; sometimes any planes at all.
    if (trial % 4 != 0) {
      const float scale = 0.002f + 0.05f * unit(rng);
      const float c = (rng() % 8 != 0 ? 1.0f : -1.0f) * (0.5f + unit(rng));
      setPlane(fan, kDen, 0.001f * (unit(rng) - 0.5f), 0.001f * (unit(rng) - 0.5f), c);
      setPlane(fan, kPu, scale, 0.3f * scale * (unit(rng) - 0.5f), c * unit(rng));
      setPlane(fan, kPv, -0.3f * scale * unit(rng), scale, c * unit(rng) * 0.5f);
    } else {
      for (int k : {kDen, kPu, kPv}) setRandomPlane(fan, k, rng);
    }
    for (int k : {kNormalX, kNormalY, kNormalZ}) setRandomPlane(fan, k, rng);
    for (int k : {kTextureU, kTextureV})
      setPlane(fan, k, 4.0f * unit(rng) - 2.0f, 0.1f * unit(rng), 8.0f * unit(rng) - 4.0f);
    if (trial % 97 == 0) setRandomPlane(fan, kTextureU, rng);
    for (auto& n : fan.cornerNormal)
      for (float& c : n) c = 2.0f * unit(rng) - 1.0f;
    for (auto& uv : fan.cornerUv)
      for (float& c : uv) c = 6.0f * unit(rng) - 3.0f;
    fan.degenerate = trial % 13 == 0;

    const int count = 1 + int(rng() % 70);
    const int x = std::max(0, face.originX + int(rng() % 120) - 60);
    const int y = face.originY + int(rng() % 120) - 60;
    std::vector<uint32_t> expected(static_cast<size_t>(count)), got(expected.size() + 16);
    shadeSurfaceRunScalar(frame, face, &fan, x, y, count, expected.data());
    for (const Version& v : versions) {
      v.run(frame, face, &fan, x, y, count, got.data());
      for (int i = 0; i < count; ++i)
        ASSERT_EQ(got[size_t(i)], expected[size_t(i)])
            << v.name << ", trial " << trial << ", sample " << i << " of " << count;
    }
    // Whether the run's first sample lies inside the triangle, about as the kernel decides it.
    const float sy = float(y - face.originY), sx = float(x - face.originX);
    const auto plane = [&](int k) { return fan.c[k] + fan.b[k] * sy + fan.a[k] * sx; };
    const float den = plane(kDen), u = plane(kPu), w = plane(kPv);
    (den > 0 && u >= 0 && w >= 0 && u + w <= den ? inside : outside) += 1;
  }
  // Both branches of the kernel are reached many times.
  EXPECT_GT(inside, 1000);
  EXPECT_GT(outside, 2000);
}

// The rows of a rendered frame, colored by every version from the same SurfaceSetup, as colors
// and as image bytes (the scalar colors packed by packBgrScalar), the bytes written up to the
// row's end and not one past it.
void expectRowsAgree(const Scene& scene, const std::string& label) {
  Renderer renderer(scene, "zbuffer");
  const Camera camera = makeCamera(scene);
  renderer.renderFrame(camera);
  const FrameBuffer& fb = renderer.buffer();
  std::vector<Mat4> modelView;
  for (uint32_t k = 0; k < scene.instanceCount(); ++k)
    modelView.push_back(camera.view * scene.modelMatrix(k));
  SurfaceSetup setup(scene, scene.settings.shading);
  setup.begin(modelView, camera, fb.width(), fb.height());
  std::vector<uint32_t> expected(size_t(fb.width()) + 16), got(expected.size());
  const size_t rowBytes = 3 * size_t(fb.width());
  constexpr uint8_t kCanary = 0xA5;
  std::vector<uint8_t> expectedBytes(rowBytes), gotBytes(rowBytes + 64);
  const uint32_t background = 0x123456;
  for (int y = 0; y < fb.height(); ++y) {
    shadeSurfaceRowScalar(setup, fb.row(y), fb.width(), y, background, expected.data());
    packBgrScalar(expected.data(), fb.width(), expectedBytes.data());
    for (const Version& v : vectorVersions()) {
      v.row(setup, fb.row(y), fb.width(), y, background, got.data());
      for (int x = 0; x < fb.width(); ++x)
        ASSERT_EQ(got[size_t(x)], expected[size_t(x)])
            << label << ", " << v.name << ", sample " << x << ", " << y;
      std::fill(gotBytes.begin(), gotBytes.end(), kCanary);
      v.bgrRow(setup, fb.row(y), fb.width(), y, background, gotBytes.data());
      for (size_t i = 0; i < rowBytes; ++i)
        ASSERT_EQ(gotBytes[i], expectedBytes[i])
            << label << ", " << v.name << " bytes, pixel " << i / 3 << ", " << y;
      for (size_t i = rowBytes; i < gotBytes.size(); ++i)
        ASSERT_EQ(gotBytes[i], kCanary) << label << ", " << v.name << ": byte " << i - rowBytes
                                        << " past row " << y << " written";
    }
  }
  EXPECT_GT(test::coveredSamples(fb), 1000u) << label;
}

TEST(SurfaceKernel, VectorRowsGiveTheScalarBitsOnRealFrames) {
  if (vectorVersions().empty()) GTEST_SKIP() << "this CPU has no AVX2";
  for (const ShadingMode mode : {ShadingMode::Normal, ShadingMode::Phong, ShadingMode::Texture}) {
    for (const std::string name : {"spot", "shapes", "teapot"}) {
      SceneSettings s = test::projectScene(name);
      if (!std::filesystem::exists(s.modelPath)) continue;
      // A width of whole blocks of eight, and one that ends in a part of a block.
      for (const int width : {160, 157}) {
        s.width = width;
        s.height = 160;
        s.shading = mode;
        s.cull = name != "teapot";
        Warnings warnings;
        expectRowsAgree(loadScene(s, warnings),
                        name + " " + shadingModeName(mode) + " " + std::to_string(width));
      }
    }
  }
}

}  // namespace
}  // namespace zrender
