#pragma once

#include <string>

#include "zrender/cli/bench/BenchComparison.hpp"
#include "zrender/cli/bench/BenchResults.hpp"

namespace zrender {

// The bench report a browser opens (`--html`, docs/bench.md, HTML report): one self-contained
// page (styles, script and SVG inline, pictures as data: URIs, nothing fetched) with the run's
// build and machine; per scene its frame, the culling counters and a chart of each algorithm's
// visibility and shading samples on one axis; and a table of every cell, sorted by a click on
// a column's header. `baseline` and `comparison` are null without --baseline.
std::string benchHtml(const BenchRun& run, const BenchRun* baseline,
                      const BenchComparison* comparison);

}  // namespace zrender
