// Fuzz target: render a fuzzed small model with every algorithm of algorithmNames() and check
// The guarantee of docs/design.md, The algorithms: the FrameBuffer (depth and id of every sample)
// and the color image of each algorithm are bit-identical to zbuffer's. Algorithms join
// automatically as they are registered in the factory. The input format is in RenderCase.hpp.

#include <cstdint>
#include <exception>
#include <memory>
#include <string>

#include "FuzzSupport.hpp"
#include "RenderCase.hpp"
#include "zrender/io/SceneFiles.hpp"
#include "zrender/io/obj/ObjLoader.hpp"

namespace {

using zrender::fuzz::fail;

// Bounds on the work per input, so executions stay in the thousands per second.
constexpr size_t kMaxInput = 1 << 13;
constexpr size_t kMaxFaces = 256;
constexpr size_t kMaxCorners = 2048;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  zrender::fuzz::RenderCase input;
  if (size > kMaxInput || !zrender::fuzz::decodeRenderCase(data, size, input)) return 0;

  zrender::Warnings warnings;
  std::shared_ptr<const zrender::Mesh> mesh;
  try {
    mesh = std::make_shared<const zrender::Mesh>(zrender::loadObjFromText(
        input.obj, zrender::fuzz::scratchFolder() / "render.obj", warnings));
  } catch (const zrender::InputError&) {
    return 0;  // the loader's own target checks its errors
  }
  if (mesh->faceCount() > kMaxFaces || mesh->corners.size() > kMaxCorners) return 0;

  try {
    zrender::validateScene(input.settings, "fuzz");
  } catch (const zrender::InputError& e) {
    fail(std::string("a preset scene does not validate: ") + e.what());
  }
  try {
    zrender::Scene scene =
        zrender::makeScene(input.settings, mesh, zrender::loadTexture(input.settings));
    scene.materialTextures = zrender::loadMaterialTextures(*mesh, warnings);
    const std::string difference = zrender::fuzz::checkAlgorithmsAgree(scene, input.twice);
    if (!difference.empty()) fail(difference);
  } catch (const zrender::InputError&) {
    // A model too large to frame (its bounding sphere overflows the camera) is bad input with
    // a clean error; HardFiles.HugeCoordinatesRenderOrFailCleanly checks that error.
    return 0;
  } catch (const std::exception& e) {
    fail(std::string("unexpected exception: ") + e.what());
  }
  return 0;
}
