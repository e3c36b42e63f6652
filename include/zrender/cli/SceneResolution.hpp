#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "zrender/base/Error.hpp"
#include "zrender/scene/SceneSettings.hpp"
#include "zrender/scene/Transforms.hpp"

namespace zrender {

// Scene options (docs/design.md, Command line) that override settings.json; unset ones keep the
// file's value.
struct SceneOverrides {
  std::optional<int> width, height;
  std::optional<Vec3> eye, target, up, axis;
  std::optional<double> fov, aspect, near, far, angle;
  bool fit = false;    // --fit: frame the model, moving eye, target, near and far
  bool noFit = false;  // --no-fit: a model file without fit
  std::optional<std::string> shading;
  std::optional<int> msaa;
  bool noCull = false;
  bool cull = false;  // --cull: cull back faces even where the scene says "cull": false
};

// The scene to render: the settings entry named `scene` (or, when `scene` is a model file and
// not a key, that model with the defaults and fit), with the overrides applied and validated.
// Resolves the settings file as docs/design.md, Command line says. With `moreModels`, `scene` and
// they are model files, the objects of one scene, each at its own coordinates. Throws InputError.
SceneSettings resolveScene(const std::string& scene,
                           const std::optional<std::filesystem::path>& settingsOption,
                           const SceneOverrides& overrides, Warnings& warnings,
                           const std::vector<std::string>& moreModels = {});

// The settings file used when --settings is absent: ./settings.json, else, for an executable in
// its build tree (CMakeCache.txt beside it or one folder up), the source tree's. Empty when
// neither exists: an installed zrender reads only the files it is given or finds in the
// current folder.
std::filesystem::path defaultSettingsPath();

// Applies the overrides to a scene; throws InputError for an unknown shading name.
void applyOverrides(const SceneOverrides& overrides, SceneSettings& scene);

// The scene used when SCENE is a model file rather than a settings key: the defaults, and fit
// around the camera options given (SceneSettings::fitKeeps, set by resolveScene).
SceneSettings defaultSceneForModel(const std::filesystem::path& modelPath);

}  // namespace zrender
