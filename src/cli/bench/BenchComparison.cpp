#include "zrender/cli/bench/BenchComparison.hpp"

#include <algorithm>
#include <random>

#include "zrender/base/Median.hpp"

namespace zrender {

namespace {

// The median of `n` draws with replacement from `values`, into `scratch`.
double resampledMedian(const std::vector<double>& values, std::mt19937_64& rng,
                       std::vector<double>& scratch) {
  scratch.resize(values.size());
  // Modulo's bias is below 1e-17 for the sizes of a bench (at most 100000 samples).
  for (double& v : scratch) v = values[rng() % values.size()];
  const size_t n = scratch.size(), mid = n / 2;
  std::nth_element(scratch.begin(), scratch.begin() + mid, scratch.end());
  if (n % 2) return scratch[mid];
  const double upper = scratch[mid];
  return 0.5 * (*std::max_element(scratch.begin(), scratch.begin() + mid) + upper);
}

}  // namespace

double sortedQuantile(const std::vector<double>& sorted, double fraction) {
  if (sorted.empty()) return 0;
  const double at = fraction * double(sorted.size() - 1);
  const size_t below = size_t(at);
  if (below + 1 >= sorted.size()) return sorted.back();
  return sorted[below] + (at - double(below)) * (sorted[below + 1] - sorted[below]);
}

std::vector<double> probedFrameTimes(const BenchCell& cell) {
  std::vector<double> times = cell.frame.samples;
  if (cell.probe.samples.size() != times.size()) return times;
  for (size_t i = 0; i < times.size(); ++i)
    if (cell.probe.samples[i] > 0) times[i] /= cell.probe.samples[i];
  return times;
}

RatioInterval medianRatioInterval(const std::vector<double>& current,
                                  const std::vector<double>& baseline, uint64_t seed,
                                  int resamples) {
  RatioInterval r;
  const double base = median(baseline);
  if (current.empty() || baseline.empty() || base <= 0) return r;
  r.ratio = median(current) / base;
  std::mt19937_64 rng(seed);
  std::vector<double> ratios, scratch;
  ratios.reserve(size_t(resamples));
  for (int i = 0; i < resamples; ++i) {
    const double c = resampledMedian(current, rng, scratch);
    const double b = resampledMedian(baseline, rng, scratch);
    if (b > 0) ratios.push_back(c / b);
  }
  if (ratios.empty()) return r;
  std::sort(ratios.begin(), ratios.end());
  r.low = sortedQuantile(ratios, 0.025);
  r.high = sortedQuantile(ratios, 0.975);
  return r;
}

const char* verdictName(Verdict verdict) {
  switch (verdict) {
    case Verdict::Faster:
      return "faster";
    case Verdict::Slower:
      return "slower";
    case Verdict::NoChange:
      break;
  }
  return "no change";
}

size_t BenchComparison::count(Verdict verdict) const {
  return size_t(std::count_if(cells.begin(), cells.end(),
                              [&](const CellComparison& c) { return c.verdict == verdict; }));
}

size_t BenchComparison::failures() const {
  return size_t(
      std::count_if(cells.begin(), cells.end(), [](const CellComparison& c) { return c.failed; }));
}

const CellComparison* BenchComparison::find(const BenchKey& key) const {
  for (const CellComparison& c : cells)
    if (c.key == key) return &c;
  return nullptr;
}

BenchComparison compareRuns(const BenchRun& current, const BenchRun& baseline,
                            const std::string& baselineFile, std::optional<double> maxSlowdownPct) {
  BenchComparison out;
  out.baselineFile = baselineFile;
  out.baselineCommit = baseline.commit;
  out.baselineDate = baseline.date;
  out.maxSlowdownPct = maxSlowdownPct;
  auto findIn = [](const BenchRun& run, const BenchKey& key) -> const BenchCell* {
    for (const BenchCell& c : run.cells)
      if (c.key == key) return &c;
    return nullptr;
  };
  for (const BenchCell& cell : current.cells) {
    const BenchCell* base = findIn(baseline, cell.key);
    if (!base) {
      out.onlyInCurrent.push_back(cell.key);
      continue;
    }
    CellComparison c;
    c.key = cell.key;
    c.baselineMs = base->frame.median;
    c.currentMs = cell.frame.median;
    c.ratio = medianRatioInterval(cell.frame.samples, base->frame.samples);
    c.probed = medianRatioInterval(probedFrameTimes(cell), probedFrameTimes(*base));
    if (c.ratio.low > 1 && c.probed.low > 1)
      c.verdict = Verdict::Slower;
    else if (c.ratio.high < 1 && c.probed.high < 1)
      c.verdict = Verdict::Faster;
    const double limit = maxSlowdownPct ? 1 + *maxSlowdownPct / 100 : 0;
    c.failed = maxSlowdownPct && c.ratio.low > limit && c.probed.low > limit;
    out.cells.push_back(c);
  }
  for (const BenchCell& cell : baseline.cells)
    if (!findIn(current, cell.key)) out.onlyInBaseline.push_back(cell.key);
  return out;
}

}  // namespace zrender
