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
  std::optional<std::filesystem::path> settings, output, depth, ids, normals;
  int repeat = 1;
  bool json = false;
  bool stats = false;
  int turntable = 0;  // frames; 0 = a single image
  int threads = 1;    // per frame, or for several views at once (docs/design.md, Threads)
  std::optional<std::filesystem::path> contactSheet;
  // Views (docs/design.md, Views): relative to the scene's camera, degrees and a magnification.
  std::optional<double> azimuth, elevation, zoom;
  int orbit = 0;                                 // views around the up axis per ring; 0 = no orbit
  std::vector<double> orbitElevations;           // one ring per elevation, degrees
  std::optional<std::string> frames;             // "A:B": views [A, B)
  std::optional<std::string> shard;              // "I/N": the I-th of N parts, from 0
  bool skipExisting = false;                     // leave out views whose files all exist
  std::optional<std::filesystem::path> cameras;  // the camera manifest (transforms.json)
  bool camerasOnly = false;                      // write the manifest, render nothing
  bool quiet = false;                            // no summary line, no warnings
  std::string progress = "auto";                 // auto, bar, lines or none
  // Reference images (docs/design.md, Reference images), compared with the image -o, --depth
  // or --ids writes; the pixels that may differ before the run fails (exit 3).
  std::optional<std::filesystem::path> reference, referenceDepth, referenceIds;
  std::optional<long long> referenceTolerance;  // pixels; default 0
  SceneOverrides overrides;
};

// Renders the scene (or a turntable of it) and writes its outputs. Throws InputError for bad
// input; returns the exit status.
int runRender(const RenderOptions& options, std::ostream& out, std::ostream& err);

}  // namespace zrender
