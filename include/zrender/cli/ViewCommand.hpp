#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "zrender/cli/SceneResolution.hpp"
#include "zrender/view/ViewKeys.hpp"

namespace zrender {

// `zrender view SCENE [options]`, after parsing.
struct ViewOptions {
  std::string scene;
  std::string algorithm = "zbuffer";
  std::optional<std::filesystem::path> settings, saveLast, contactSheet;
  std::vector<ViewKey> keys;  // --keys
  int keyInterval = 1;        // frames between two keys of --keys
  int frames = 0;             // --frames; 0: until quit
  int threads = 1;            // per frame
  SceneOverrides overrides;
};

// Without --width and --height, the window shows the scene at most this many pixels a side.
constexpr int kViewMaxSide = 900;

// Opens the window, shows the scene orbiting until quit or --frames, then writes --save-last and
// --contact-sheet and prints the command line that renders the last frame. Throws InputError
// for bad input and when there is no display; returns the exit status.
int runView(const ViewOptions& options, std::ostream& out, std::ostream& err);

}  // namespace zrender
