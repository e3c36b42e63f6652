#include "support/SettingsParsing.hpp"

#include "zrender/base/Error.hpp"

namespace zrender::test {

namespace fs = std::filesystem;

SettingsFile parse(const std::string& text, Warnings& warnings, const fs::path& path) {
  return parseSettings(text, path, warnings);
}

SettingsFile parse(const std::string& text) {
  Warnings warnings;
  return parse(text, warnings);
}

std::string parseError(const std::string& text) {
  try {
    parse(text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

std::string bunnyWith(const std::string& members) {
  return R"({"bunny": {"path": "m.obj", )" + members + "}}";
}

std::string bunnyError(const std::string& members) {
  return parseError(bunnyWith(members));
}

std::string validateError(const SceneSettings& scene) {
  try {
    validateScene(scene, "command line");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

SceneSettings validScene() {
  SceneSettings scene;
  scene.name = "s";
  scene.modelPath = "m.obj";
  scene.eye = cv::Vec3d(0, 0, 5);
  return scene;
}

}  // namespace zrender::test
