#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "zrender/cli/bench/BenchResults.hpp"

namespace zrender {

// The ratio of two medians (current / baseline: above 1 is slower) and its 95% confidence
// interval, from a percentile bootstrap: each set of samples is resampled with replacement
// `resamples` times, with a fixed seed, so a comparison gives the same interval every time
// (docs/bench.md, Comparing with a baseline).
struct RatioInterval {
  double ratio = 1, low = 1, high = 1;
};
RatioInterval medianRatioInterval(const std::vector<double>& current,
                                  const std::vector<double>& baseline, uint64_t seed = 20261128,
                                  int resamples = 10000);

// The value below which a `fraction` of the ascending `sorted` values lie, linear between
// neighbours; 0 for none. The bootstrap's interval ends and the report's quartiles.
double sortedQuantile(const std::vector<double>& sorted, double fraction);

// A cell's frame times, each divided by the machine-speed probe run just before it
// (MachineProbe.hpp): what a comparison compares.
std::vector<double> probedFrameTimes(const BenchCell& cell);

enum class Verdict { NoChange, Faster, Slower };
const char* verdictName(Verdict verdict);  // "no change", "faster", "slower"

// One cell found in both runs: its frame times compared.
struct CellComparison {
  BenchKey key;
  double baselineMs = 0, currentMs = 0;  // medians of frame_ms
  RatioInterval ratio;                   // of the medians of frame_ms
  RatioInterval probed;                  // of the medians of probedFrameTimes
  // Slower or faster when both intervals lie wholly above or below 1: a change of the machine's
  // speed moves the first only, the probe's own noise the second only.
  Verdict verdict = Verdict::NoChange;
  // With --max-slowdown PCT: both intervals lie above 1 + PCT/100, so the slowdown is both
  // larger than PCT and significant.
  bool failed = false;
};

struct BenchComparison {
  std::string baselineFile, baselineCommit, baselineDate;
  std::optional<double> maxSlowdownPct;
  std::vector<CellComparison> cells;                    // in the current run's order
  std::vector<BenchKey> onlyInCurrent, onlyInBaseline;  // listed, not errors

  size_t count(Verdict verdict) const;
  size_t failures() const;
  // The comparison of `key`, or null when the baseline has no such cell.
  const CellComparison* find(const BenchKey& key) const;
};

BenchComparison compareRuns(const BenchRun& current, const BenchRun& baseline,
                            const std::string& baselineFile, std::optional<double> maxSlowdownPct);

}  // namespace zrender
