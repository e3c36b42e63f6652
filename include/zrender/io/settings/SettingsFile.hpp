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

}  // namespace zrender
