#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "zrender/cli/SceneResolution.hpp"

namespace zrender {

// `zrender bench [SCENE...] [options]`, after parsing.
struct BenchOptions {
  std::vector<std::string> scenes;      // empty: every scene with "bench": true
  std::vector<std::string> algorithms;  // empty: all
  int repeat = 5;
  int threads = 1;  // per frame; more than 1 also times one thread, for the speed-up
  std::optional<std::filesystem::path> settings, markdown, json, chart;
  SceneOverrides overrides;
};

// Times every algorithm on every scene, checks that they agree with the z-buffer, prints the
// table and writes its files. Throws InputError for bad input; returns the exit status (1 when
// an algorithm disagrees).
int runBench(const BenchOptions& options, std::ostream& out, std::ostream& err);

}  // namespace zrender
