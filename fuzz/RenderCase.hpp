#pragma once

// The render fuzz target's input format and its check, shared with the test suite
// (tests/visibility/AlgorithmsAgreeTest.cpp), which replays every input the fuzzer found (kept
// in fuzz/corpus/render).
//
// Input: 4 option bytes, then OBJ text.
//   byte 0: bit 0 culling off, bit 1 MSAA 4, bits 2-4 shading mode, bits 5-6 camera preset
//   byte 1: model rotation angle, 360/256 degrees per step, about the axis (1, 2, 3)
//   byte 2: image size, width 16 + 2 * (low 4 bits), height 16 + 2 * (high 4 bits)
//   byte 3: bit 0 render every frame twice (buffers are reused), bit 1 a 2 x 1 x 2 grid

#include <cstdint>
#include <cstring>
#include <memory>
#include <string>

#include "zrender/io/settings/SettingsFile.hpp"
#include "zrender/render/Renderer.hpp"
#include "zrender/scene/Camera.hpp"
#include "zrender/scene/Scene.hpp"
#include "zrender/scene/SceneValidation.hpp"
#include "zrender/scene/ShadingMode.hpp"
#include "zrender/visibility/VisibilityAlgorithm.hpp"

namespace zrender::fuzz {

constexpr size_t kRenderOptionBytes = 4;

struct RenderCase {
  SceneSettings settings;
  bool twice = false;  // render each frame twice and compare (buffers are reused)
  std::string obj;     // the model's text
};

// The camera presets: two framed by fit, and two fixed ones for small integer coordinates
// (what fuzzed files mostly hold) that cut the model with the near plane or sit inside it.
inline void applyCameraPreset(int preset, SceneSettings& s) {
  switch (preset) {
    case 0:  // fit, looking down -z
      s.fit = true;
      break;
    case 1:  // fit, from a corner
      s.fit = true;
      s.eye = Vec3(3, 2, 4);
      s.target = Vec3(0, 0, 0);
      break;
    case 2:  // fixed: the near plane at z = 1 crosses models spanning z in 0..3
      s.eye = Vec3(0.5, 0.5, 2.0);
      s.target = Vec3(0.5, 0.5, 0.0);
      s.near = 1.0;
      s.far = 6.0;
      s.fovy = 90.0;
      break;
    default:  // fixed: eye inside the unit cube, wide view
      s.eye = Vec3(0.25, 0.3, 0.35);
      s.target = Vec3(1.0, 0.5, -0.25);
      s.near = 0.01;
      s.far = 20.0;
      s.fovy = 120.0;
      break;
  }
}

// Decodes an input; false when it is too short for the option bytes.
inline bool decodeRenderCase(const uint8_t* data, size_t size, RenderCase& out) {
  if (size < kRenderOptionBytes) return false;
  const uint8_t flags = data[0], angle = data[1], dims = data[2], extra = data[3];
  SceneSettings& s = out.settings;
  s = SceneSettings();
  s.name = "fuzz";
  s.width = 16 + 2 * (dims & 15);
  s.height = 16 + 2 * (dims >> 4);
  s.cull = !(flags & 1);
  s.msaa = (flags & 2) ? 4 : 1;
  const auto& modes = shadingModeNames();
  s.shading = *parseShadingMode(modes[((flags >> 2) & 7) % modes.size()]);
  applyCameraPreset((flags >> 5) & 3, s);
  s.angle = angle * (360.0 / 256.0);
  s.axis = Vec3(1, 2, 3);
  if (extra & 2) {
    Grid grid;
    grid.count = {2, 1, 2};
    grid.spacing = Vec3(1.5, 0.0, 1.5);
    s.grid = grid;
  }
  out.twice = extra & 1;
  out.obj.assign(reinterpret_cast<const char*>(data) + kRenderOptionBytes,
                 size - kRenderOptionBytes);
  return true;
}

inline std::string describeDifference(const FrameBuffer& a, const FrameBuffer& b) {
  if (a.width() != b.width() || a.height() != b.height()) return "sizes differ";
  for (int y = 0; y < a.height(); ++y) {
    for (int x = 0; x < a.width(); ++x) {
      const DepthKey ka = a.row(y)[x], kb = b.row(y)[x];
      if (ka == kb) continue;
      return "first at sample (" + std::to_string(x) + ", " + std::to_string(y) + "): id " +
             std::to_string(int64_t(keyFaceId(ka))) + " depth " + std::to_string(keyDepth(ka)) +
             " against id " + std::to_string(int64_t(keyFaceId(kb))) + " depth " +
             std::to_string(keyDepth(kb));
    }
  }
  return "color only";
}

inline bool sameImage(const cv::Mat& a, const cv::Mat& b) {
  return samePixels(a, b);
}

// Renders the scene with every algorithm of algorithmNames() and compares each one's buffer
// and color image with the first's (zbuffer). Returns "" when all agree, else what differs.
inline std::string checkAlgorithmsAgree(const Scene& scene, bool twice) {
  const Camera camera = makeCamera(scene);
  std::unique_ptr<Renderer> reference;
  for (const std::string& name : algorithmNames()) {
    auto renderer = std::make_unique<Renderer>(scene, name);
    renderer->renderFrame(camera);
    if (twice) {
      const FrameBuffer first = renderer->buffer();
      const cv::Mat firstColor = renderer->color().clone();
      renderer->renderFrame(camera);
      if (!(renderer->buffer() == first) || !sameImage(renderer->color(), firstColor)) {
        return name + ": the second frame differs from the first (" +
               describeDifference(first, renderer->buffer()) + ")";
      }
    }
    if (!reference) {
      reference = std::move(renderer);
      continue;
    }
    if (!(renderer->buffer() == reference->buffer()) ||
        !sameImage(renderer->color(), reference->color())) {
      return name + " differs from " + reference->algorithm().name() + ": " +
             describeDifference(reference->buffer(), renderer->buffer());
    }
  }
  return "";
}

}  // namespace zrender::fuzz
