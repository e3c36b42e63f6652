// Fuzz target: settings.json parsing and scene validation. Whatever the bytes, parseSettings
// and validateScene either succeed or throw InputError with a one-line message naming the file
// (or the scene); and a scene that validates gives a camera with finite matrices, since a NaN
// camera would silently render an empty picture.

#include <cmath>
#include <cstdint>
#include <exception>
#include <memory>
#include <string>

#include "FuzzSupport.hpp"
#include "zrender/io/settings/SettingsFile.hpp"
#include "zrender/scene/Camera.hpp"
#include "zrender/scene/Mesh.hpp"
#include "zrender/scene/Scene.hpp"
#include "zrender/scene/SceneValidation.hpp"

namespace {

using zrender::fuzz::fail;

constexpr size_t kMaxInput = 1 << 16;
const char* const kFile = "fuzz/settings.json";

bool finite(const zrender::Mat4& m) {
  for (int i = 0; i < 16; ++i) {
    if (!std::isfinite(m.val[i])) return false;
  }
  return true;
}

// A unit triangle, so that makeScene and makeCamera (with fit) have bounds to work on.
std::shared_ptr<const zrender::Mesh> unitTriangle() {
  auto mesh = std::make_shared<zrender::Mesh>();
  mesh->positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  mesh->corners = {{0, -1, -1}, {1, -1, -1}, {2, -1, -1}};
  mesh->faceStart = {0, 3};
  mesh->faceMaterial = {-1};
  return mesh;
}

void checkCamera(zrender::SceneSettings scene, const std::string& where) {
  static const std::shared_ptr<const zrender::Mesh> mesh = unitTriangle();
  // The camera does not depend on these, and they would cost time (a million grid instances)
  // or read files named by the input.
  scene.grid.reset();
  scene.texture.reset();
  zrender::Warnings warnings;
  const zrender::Scene built = zrender::makeScene(scene, mesh);
  const zrender::Camera camera = zrender::makeCamera(built);
  if (!finite(camera.view) || !finite(camera.projection)) {
    fail(where + ": validated scene gives a non-finite camera");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > kMaxInput) return 0;
  const std::string text(reinterpret_cast<const char*>(data), size);
  zrender::Warnings warnings;
  try {
    const zrender::SettingsFile file = zrender::parseSettings(text, kFile, warnings);
    for (const auto& [name, scene] : file.scenes) {
      if (scene.name != name) fail("scene name differs from its key");
      const std::string where = std::string(kFile) + ": scene '" + name + "'";
      try {
        zrender::validateScene(scene, "validate");
      } catch (const zrender::InputError& e) {
        zrender::fuzz::checkMessage(e.what(), "validate: key '", "validation error");
        continue;
      }
      checkCamera(scene, where);
    }
  } catch (const zrender::InputError& e) {
    zrender::fuzz::checkMessage(e.what(), std::string(kFile) + ":", "error");
  } catch (const std::exception& e) {
    fail(std::string("unexpected exception: ") + e.what());
  }
  for (const std::string& w : warnings) {
    zrender::fuzz::checkMessage(w, std::string(kFile) + ":", "warning");
  }
  return 0;
}
