#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "zrender/cli/SceneResolution.hpp"

namespace zrender {

// What a bench run or a saved one is written as and compared with (docs/bench.md).
struct BenchOutputs {
  // markdown "-": stdout. The markdown is appended to its file (a CI step summary).
  std::optional<std::filesystem::path> json, markdown, csv, junit, benchmarkAction, chart, html;
  std::optional<std::filesystem::path> baseline;  // a results file to compare with
  std::optional<double> maxSlowdownPct;           // a significant slowdown beyond it fails (exit 3)
};

// `zrender bench [SCENE...] [options]`, after parsing.
struct BenchOptions {
  std::vector<std::string> scenes;      // empty: every scene with "bench": true
  std::vector<std::string> algorithms;  // empty: all
  int repeat = 5;
  int warmup = 1;   // frames per renderer before the timed ones
  int threads = 1;  // per frame; more than 1 also times one thread, for the speed-up
  std::optional<std::filesystem::path> settings;
  SceneOverrides overrides;
  BenchOutputs outputs;
  std::vector<std::string> command;  // the command line, for the results file
};

// Times every algorithm on every scene, checks that they agree with the z-buffer, prints the
// table and writes its files. Throws InputError for bad input; returns the exit status:
// kExitDisagree when an algorithm disagrees, else kExitCheckFailed for a slowdown beyond
// --max-slowdown, else kExitSuccess.
int runBench(const BenchOptions& options, std::ostream& out, std::ostream& err);

// `zrender bench-report RESULTS.json [options]`: the same table, comparison and files from a
// saved results file, without rendering; the same exit statuses.
int runBenchReport(const std::filesystem::path& results, const BenchOutputs& outputs,
                   std::ostream& out, std::ostream& err);

}  // namespace zrender
