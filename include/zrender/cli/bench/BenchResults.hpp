#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <json/json.h>

namespace zrender {

// `ms` to 0.1 microsecond, as the results file holds times: a run read back from its file is
// the same run, to the last digit of every table.
double roundedMs(double ms);

// One timing of a bench cell over its frames, in milliseconds.
struct TimingSummary {
  std::vector<double> samples;          // one per timed frame, in the order they ran; roundedMs
  double median = 0, mad = 0, min = 0;  // mad: median absolute deviation from the median

  static TimingSummary of(std::vector<double> samples);
};

// What identifies a cell across runs: a baseline's cell is matched to a run's by this.
struct BenchKey {
  std::string scene, algorithm, shading;
  int width = 0, height = 0, msaa = 1;

  std::string text() const;  // "bunny/octree/512x512/msaa1/normal"
  bool operator==(const BenchKey& o) const;
};

// One scene x algorithm x size x MSAA x shading of a bench run.
struct BenchCell {
  BenchKey key;
  uint64_t faces = 0;
  double prepareMs = 0;  // once per renderer, not per frame
  // Per frame: frame = transform + raster; raster holds visibility + shade (+ resolve).
  TimingSummary frame, transform, visibility, shade, raster, probe;
  std::optional<TimingSummary> oneThreadFrame;  // with --threads above 1
  Json::Value stats;                            // the culling counters (statsToJson)
  bool identical = true;  // to the z-buffer's buffers, and to its own on one thread
};

// The frame of one scene (and size, MSAA, shading), the same for every algorithm: what the
// HTML report shows, kept in the results file so that bench-report can show it again.
struct BenchPicture {
  BenchKey key;          // algorithm: "zbuffer", whose buffers every other one equals
  std::string imageUri;  // "data:image/jpeg;base64,...", at most 480 pixels a side
};

// A whole `zrender bench` run: the results file (docs/bench-results.schema.json).
struct BenchRun {
  static constexpr int kSchema = 1;
  std::string version, commit, compiler, buildType;  // commit: "" when not built from git
  std::string cpu, date;                             // date: UTC, ISO 8601
  int cores = 0, threads = 1, repeat = 0, warmup = 0;
  std::vector<std::string> command;
  std::vector<BenchCell> cells;
  std::vector<BenchPicture> pictures;

  // The zrender build and the machine this process runs on, and the time now.
  static BenchRun describingThisProcess();
};

Json::Value benchRunToJson(const BenchRun& run);
std::string benchRunText(const BenchRun& run);  // the results file's bytes

// Reads a results file; a file that is not one throws InputError naming the file and the key.
BenchRun readBenchRun(const std::filesystem::path& path);
BenchRun benchRunFromJson(const Json::Value& json, const std::string& where);

}  // namespace zrender
