#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "zrender/cli/SceneResolution.hpp"

namespace zrender {

// `zrender SCENE [options]`, after parsing.
struct RenderOptions {
  std::string scene;                    // a settings key or a model file
  std::vector<std::string> moreModels;  // further model files: one scene of them all
  std::string algorithm = "zbuffer";
  std::optional<std::filesystem::path> settings, output, depth, ids;
  int repeat = 1;
  bool json = false;
  bool stats = false;
  int turntable = 0;  // frames; 0 = a single image
  int threads = 1;    // per frame, or for a turntable's frames at once (docs/design.md, Threads)
  std::optional<std::filesystem::path> contactSheet;
  SceneOverrides overrides;
};

// Renders the scene (or a turntable of it) and writes its outputs. Throws InputError for bad
// input; returns the exit status.
int runRender(const RenderOptions& options, std::ostream& out, std::ostream& err);

}  // namespace zrender
