#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "zrender/base/Error.hpp"
#include "zrender/scene/SceneSettings.hpp"

namespace zrender {

struct SettingsFile {
  std::filesystem::path path;
  std::map<std::string, SceneSettings> scenes;  // sorted by name
};

// Parses and validates a settings file. Throws InputError "FILE: bad JSON: ..." or
// "FILE: scene 'NAME': key 'KEY': <what is wrong>"; adds a warning for each unknown key.
SettingsFile loadSettings(const std::filesystem::path& path, Warnings& warnings);

// Same, from text already read (`path` is used for messages and to resolve model paths).
SettingsFile parseSettings(const std::string& text, const std::filesystem::path& path,
                           Warnings& warnings);

// The scene used when SCENE is a model file rather than a settings key: defaults and fit.
SceneSettings defaultSceneForModel(const std::filesystem::path& modelPath);

// For validateScene: the command-line options that set what a key's rule checks, by key
// ("project" -> "--near, --far"), so that an error names them as well as the scene.
using KeyOrigins = std::map<std::string, std::string>;

// Checks the cross-key rules (size range, near < far, fov range, eye present unless fit, ...)
// after command-line overrides; `where` prefixes messages ("settings.json: scene 'bunny'" or
// "command line"), followed by " with OPTIONS" when `origins` has the key. Throws InputError.
void validateScene(const SceneSettings& scene, const std::string& where,
                   const KeyOrigins& origins = {});

}  // namespace zrender
