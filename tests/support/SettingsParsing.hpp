#pragma once

// Helpers of the settings file and scene validation tests: parsing text as "settings.json" and
// the messages of the errors it throws.

#include <filesystem>
#include <string>

#include "zrender/io/settings/SettingsFile.hpp"
#include "zrender/scene/SceneValidation.hpp"

namespace zrender::test {

// Parses `text` as the settings file `path`.
SettingsFile parse(const std::string& text, Warnings& warnings,
                   const std::filesystem::path& path = "settings.json");
SettingsFile parse(const std::string& text);

// The message of the InputError that parsing throws, or "no error".
std::string parseError(const std::string& text);

// A scene "bunny" with a valid path plus the given members.
std::string bunnyWith(const std::string& members);

// parseError(bunnyWith(members)).
std::string bunnyError(const std::string& members);

// The message of the InputError that validateScene throws for `scene` (named "command line"),
// or "no error".
std::string validateError(const SceneSettings& scene);

// A scene that passes validateScene: eye on +z looking at the origin.
SceneSettings validScene();

}  // namespace zrender::test
