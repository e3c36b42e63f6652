#pragma once

#include <cstdint>
#include <string>

#include "zrender/cli/bench/BenchComparison.hpp"
#include "zrender/cli/bench/BenchResults.hpp"

namespace zrender {

// The texts a bench run is written as (docs/bench.md, Formats). `comparison` is null without
// --baseline.

// The table the terminal shows, then the comparison with the baseline, as GitHub-flavoured
// markdown (what `--markdown` appends to a step summary).
std::string benchMarkdown(const BenchRun& run, const BenchComparison* comparison);

// One line per cell with a header; RFC 4180 quoting. The baseline's columns are empty without
// one.
std::string benchCsv(const BenchRun& run, const BenchComparison* comparison);

// JUnit XML: one test case per cell, its time the median frame in seconds, a failure for an
// algorithm that disagrees with the z-buffer or a slowdown beyond --max-slowdown.
std::string benchJunit(const BenchRun& run, const BenchComparison* comparison);

// github-action-benchmark's customSmallerIsBetter: a list of {name, unit, value, range, extra}.
std::string benchActionJson(const BenchRun& run);

// `s` with & < > " as entities and control characters other than tab and line breaks dropped:
// text or a double-quoted attribute value in XML, SVG and HTML.
std::string xmlEscaped(const std::string& s);

// `v` with `digits` decimals ("%.*f").
std::string fixed(double v, int digits);

// A color 0xRRGGBB as CSS and SVG write it: "#rrggbb".
std::string hexColor(uint32_t rgb);

// The cell of the same scene, size, MSAA and shading rendered by the z-buffer, or null.
const BenchCell* zbufferCellOf(const BenchRun& run, const BenchCell& cell);

}  // namespace zrender
