#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "zrender/io/Settings.hpp"
#include "zrender/scene/Transforms.hpp"

namespace zrender {

// Scene options of SPEC §2 that override settings.json; unset ones keep the file's value.
struct SceneOverrides {
  std::optional<int> width, height;
  std::optional<Vec3> eye, target, up, axis;
  std::optional<double> fov, aspect, near, far, angle;
  bool fit = false;    // --fit: frame the model, moving eye, target, near and far
  bool noFit = false;  // --no-fit: a model file without fit
  std::optional<std::string> shading;
  std::optional<int> msaa;
  bool noCull = false;
};

struct RenderOptions {
  std::string scene;  // a settings key or a model file
  std::string algorithm = "zbuffer";
  std::optional<std::filesystem::path> settings, output, depth, ids;
  int repeat = 1;
  bool json = false;
  bool stats = false;
  int turntable = 0;  // frames; 0 = a single image
  std::optional<std::filesystem::path> contactSheet;
  SceneOverrides overrides;
};

struct BenchOptions {
  std::vector<std::string> scenes;      // empty: every scene with "bench": true
  std::vector<std::string> algorithms;  // empty: all
  int repeat = 5;
  std::optional<std::filesystem::path> settings, markdown, json, chart;
  SceneOverrides overrides;
};

// The scene to render: the settings entry named `scene` (or, when `scene` is a model file and
// not a key, that model with the defaults and fit), with the overrides applied and validated.
// Resolves the settings file as SPEC §2 says. Throws InputError.
SceneSettings resolveScene(const std::string& scene,
                           const std::optional<std::filesystem::path>& settingsOption,
                           const SceneOverrides& overrides, Warnings& warnings);

// The settings file used when --settings is absent: ./settings.json, else the one of the
// project the executable was built from. Empty when neither exists.
std::filesystem::path defaultSettingsPath();

// Applies the overrides to a scene; throws InputError for an unknown shading name.
void applyOverrides(const SceneOverrides& overrides, SceneSettings& scene);

// zrender's main: parses argv, runs the command, prints errors as SPEC §8 says.
// Returns the exit status (0, 1 internal failure, 2 bad input or disagreement in bench).
int runCommandLine(int argc, char** argv, std::ostream& out, std::ostream& err);

// The commands, after parsing. They throw InputError for bad input.
int runRender(const RenderOptions& options, std::ostream& out, std::ostream& err);
int runBench(const BenchOptions& options, std::ostream& out, std::ostream& err);

}  // namespace zrender
