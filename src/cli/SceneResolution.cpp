#include "zrender/cli/SceneResolution.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>

#include "zrender/base/Error.hpp"
#include "zrender/io/settings/SettingsFile.hpp"
#include "zrender/scene/SceneValidation.hpp"

namespace zrender {

namespace fs = std::filesystem;

SceneSettings defaultSceneForModel(const fs::path& modelPath) {
  SceneSettings scene;
  scene.name = modelPath.stem().string();
  scene.modelPath = modelPath;
  scene.fit = true;
  return scene;
}

fs::path defaultSettingsPath() {
  std::error_code ec;
  if (fs::is_regular_file("settings.json", ec)) return "settings.json";
  // A zrender run from its build tree (CMakeCache.txt beside it, or one folder up for the
  // tests) falls back to its source tree's settings.json; an installed one never does.
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  for (const fs::path& folder : {exe.parent_path(), exe.parent_path().parent_path()}) {
    std::ifstream cache(folder / "CMakeCache.txt");
    std::string line;
    const std::string key = "CMAKE_HOME_DIRECTORY:INTERNAL=";
    while (std::getline(cache, line)) {
      if (line.rfind(key, 0) != 0) continue;
      const fs::path settings = fs::path(line.substr(key.size())) / "settings.json";
      return fs::is_regular_file(settings, ec) ? settings : fs::path();
    }
  }
  return {};
}

void applyOverrides(const SceneOverrides& o, SceneSettings& s) {
  if (o.width) s.width = *o.width;
  if (o.height) s.height = *o.height;
  if (o.eye) s.eye = *o.eye;
  if (o.target) s.target = *o.target;
  if (o.up) s.up = *o.up;
  if (o.axis) s.axis = *o.axis;
  if (o.fov) s.fovy = *o.fov;
  if (o.aspect) s.aspect = *o.aspect;
  if (o.near) s.near = std::abs(*o.near);
  if (o.far) s.far = std::abs(*o.far);
  if (o.angle) s.angle = *o.angle;
  if (o.fit) s.fit = true;
  if (o.noFit) s.fit = false;
  if (o.msaa) s.msaa = *o.msaa;
  if (o.noCull) s.cull = false;
  if (o.cull) s.cull = true;
  if (o.shading) {
    const auto mode = parseShadingMode(*o.shading);
    if (!mode) {
      std::string list;
      for (const auto& n : shadingModeNames()) list += (list.empty() ? "" : ", ") + n;
      throw InputError("command line: --shading: unknown shading '" + *o.shading +
                       "' (choose from: " + list + ")");
    }
    s.shading = *mode;
  }
}

namespace {

// How many scene names an "unknown scene" error lists.
constexpr size_t kScenesNamed = 20;

// Which of the given options feed each key's rule in validateScene: eye is checked against
// target, up against the viewing direction target - eye.
KeyOrigins keyOrigins(const SceneOverrides& o) {
  KeyOrigins origins;
  const auto add = [&](const std::string& key, bool given, const char* option) {
    if (!given) return;
    std::string& list = origins[key];
    list += (list.empty() ? "" : ", ") + std::string(option);
  };
  add("width", o.width.has_value(), "--width");
  add("height", o.height.has_value(), "--height");
  add("project", o.fov.has_value(), "--fov");
  add("project", o.aspect.has_value(), "--aspect");
  add("project", o.near.has_value(), "--near");
  add("project", o.far.has_value(), "--far");
  add("msaa", o.msaa.has_value(), "--msaa");
  add("angle", o.angle.has_value(), "--angle");
  add("axis", o.axis.has_value(), "--axis");
  add("target", o.target.has_value(), "--target");
  add("eye", o.eye.has_value(), "--eye");
  add("eye", o.target.has_value(), "--target");
  add("up", o.up.has_value(), "--up");
  add("up", o.eye.has_value(), "--eye");
  add("up", o.target.has_value(), "--target");
  return origins;
}

}  // namespace

SceneSettings resolveScene(const std::string& scene, const std::optional<fs::path>& settingsOption,
                           const SceneOverrides& overrides, Warnings& warnings,
                           const std::vector<std::string>& moreModels) {
  std::error_code ec;
  if (!moreModels.empty()) {
    // Several model files: one scene of them all, each at its own coordinates.
    SceneSettings result = defaultSceneForModel(scene);
    for (const std::string& file : moreModels) {
      if (!fs::is_regular_file(file, ec))
        throw InputError(file + ": no such model file (several scenes name model files only)");
    }
    if (!fs::is_regular_file(scene, ec))
      throw InputError(scene + ": no such model file (several scenes name model files only)");
    result.objects.push_back(SceneObject{scene});
    for (const std::string& file : moreModels) result.objects.push_back(SceneObject{file});
    if (!overrides.fit) {
      result.fitKeeps = FitKeeps{overrides.eye.has_value(), overrides.target.has_value(),
                                 overrides.near.has_value(), overrides.far.has_value()};
    }
    applyOverrides(overrides, result);
    validateScene(result, "command line: scene '" + scene + "'", keyOrigins(overrides));
    return result;
  }
  const fs::path settingsPath = settingsOption ? *settingsOption : defaultSettingsPath();
  SceneSettings result;
  std::string where;
  bool found = false;
  std::string known;
  if (!settingsPath.empty() && (settingsOption || fs::exists(settingsPath, ec))) {
    const SettingsFile file = loadSettings(settingsPath, warnings);
    const auto it = file.scenes.find(scene);
    if (it != file.scenes.end()) {
      result = it->second;
      where = settingsPath.string() + ": scene '" + scene + "'";
      result.where = where;
      found = true;
    }
    // The first few names: a file may hold any number.
    size_t listed = 0;
    for (const auto& entry : file.scenes) {
      if (listed++ < kScenesNamed) known += (known.empty() ? "" : ", ") + entry.first;
    }
    if (listed > kScenesNamed) known += " and " + std::to_string(listed - kScenesNamed) + " more";
  }
  if (!found) {
    if (fs::is_regular_file(scene, ec)) {
      result = defaultSceneForModel(scene);
      // Fit frames the model around what the user typed; --fit frames it on its own.
      if (!overrides.fit) {
        result.fitKeeps = FitKeeps{overrides.eye.has_value(), overrides.target.has_value(),
                                   overrides.near.has_value(), overrides.far.has_value()};
      }
      where = "command line: scene '" + scene + "'";
    } else if (settingsPath.empty()) {
      throw InputError(scene + ": no such scene or model file (no settings.json found)");
    } else {
      throw InputError(settingsPath.string() + ": unknown scene '" + scene +
                       "' and no model file of that name (scenes: " + known + ")");
    }
  }
  applyOverrides(overrides, result);
  validateScene(result, where, keyOrigins(overrides));
  return result;
}

}  // namespace zrender
