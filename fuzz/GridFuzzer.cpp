// Fuzz target: grid counts, spacings and the model's rotation against the face-id limit
// (docs/design.md, Limits). A scene is refused by validateScene (a clean InputError) or by
// makeScene exactly when its faces, all instances counted, pass kMaxSceneFaces; a scene small
// enough is rendered by every algorithm, which must agree with the z-buffer.
//
// Input: bytes 0-1 and bit 7 of byte 27 the face count - 1 (17 bits, little-endian), bytes 2-13
// three grid counts (32-bit little-endian, as given: most are out of range), bytes 14-25 three
// spacings (floats, any bits), byte 26 the rotation angle (360/256 degrees per step), bits 0-2 of
// byte 27 the axis (one of 8); the rest seeds the triangles' corners.

#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "FuzzSupport.hpp"
#include "RenderCase.hpp"
#include "zrender/scene/SceneValidation.hpp"

namespace {

using zrender::fuzz::fail;

constexpr size_t kHeader = 28;
// The most faces x instances rendered per input, so executions stay in the hundreds a second.
constexpr uint64_t kMaxRendered = 2048;

uint32_t littleEndian32(const uint8_t* p) {
  return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

// `faces` triangles in the cube [-1, 1]^3, corners from a generator seeded by `seed`.
std::shared_ptr<const zrender::Mesh> triangles(uint32_t faces, uint64_t seed) {
  auto mesh = std::make_shared<zrender::Mesh>();
  uint64_t state = seed | 1;
  const auto next = [&] {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return double(state >> 40) / double(1ull << 24) * 2.0 - 1.0;
  };
  const uint32_t corners = faces < 64 ? 3 * faces : 192;  // large meshes share corners
  for (uint32_t i = 0; i < corners; ++i) mesh->positions.emplace_back(next(), next(), next());
  for (uint32_t f = 0; f < faces; ++f) {
    mesh->faceStart.push_back(uint32_t(mesh->corners.size()));
    for (uint32_t c = 0; c < 3; ++c) {
      zrender::Corner corner;
      corner.position = int32_t((3 * f + c) % corners);
      mesh->corners.push_back(corner);
    }
  }
  mesh->faceStart.push_back(uint32_t(mesh->corners.size()));
  mesh->faceMaterial.assign(faces, -1);
  return mesh;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < kHeader) return 0;
  const uint32_t faces = uint32_t(data[0] | data[1] << 8 | (data[27] >> 7) << 16) + 1;
  zrender::SceneSettings s;
  s.name = "fuzz";
  s.width = 24;
  s.height = 24;
  s.fit = true;
  zrender::Grid grid;
  for (int i = 0; i < 3; ++i) {
    grid.count[size_t(i)] = int(littleEndian32(data + 2 + 4 * i));
    float spacing;
    std::memcpy(&spacing, data + 14 + 4 * i, sizeof spacing);
    grid.spacing[i] = spacing;
  }
  s.grid = grid;
  s.angle = data[26] * (360.0 / 256.0);
  const uint8_t axis = data[27] & 7;
  s.axis = zrender::Vec3(axis & 1, (axis >> 1) & 1, axis == 0 ? 1 : (axis >> 2) & 1);
  uint64_t seed = 0;
  for (size_t i = kHeader; i < size && i < kHeader + 8; ++i) seed = seed << 8 | data[i];

  try {
    zrender::validateScene(s, "fuzz");
  } catch (const zrender::InputError& e) {
    zrender::fuzz::checkMessage(e.what(), "fuzz: ", "validation error");
    return 0;
  }
  const uint64_t instances = uint64_t(s.grid->instanceCount());
  const uint64_t total = uint64_t(faces) * instances;
  const auto mesh = triangles(faces, seed);
  std::unique_ptr<zrender::Scene> scene;
  try {
    scene = std::make_unique<zrender::Scene>(zrender::makeScene(s, mesh));
  } catch (const zrender::InputError& e) {
    if (total <= zrender::kMaxSceneFaces)
      fail(std::to_string(total) + " faces refused: " + e.what());
    zrender::fuzz::checkMessage(e.what(), "scene 'fuzz': ", "face-count error");
    if (std::string(e.what()).find(std::to_string(total) + " faces") == std::string::npos)
      fail("the face-count error does not name the count: " + std::string(e.what()));
    return 0;
  }
  if (total > zrender::kMaxSceneFaces) fail(std::to_string(total) + " faces accepted");
  if (uint64_t(scene->faceCount()) != total) fail("faceCount() is not faces x instances");
  if (total > kMaxRendered) return 0;
  try {
    const std::string difference = zrender::fuzz::checkAlgorithmsAgree(*scene, false);
    if (!difference.empty()) fail(difference);
  } catch (const zrender::InputError&) {
    return 0;  // a scene too large to frame (spacings near the float limit): a clean error
  }
  return 0;
}
