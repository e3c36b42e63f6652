#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace zrender {

// Per-frame counters (docs/design.md, Timings and JSON: `stats`). Counters an algorithm does not
// use stay 0.
struct RenderStats {
  uint64_t trianglesBackfaceCulled = 0;
  uint64_t trianglesClippedAway = 0;
  uint64_t trianglesDegenerate = 0;
  uint64_t trianglesRasterized = 0;  // pieces (or polygons' pieces) that reached pixel work
  uint64_t trianglesHzbCulled = 0;
  uint64_t octreeNodesVisited = 0;
  uint64_t octreeNodesCulled = 0;
  uint64_t pixelsTested = 0;   // depth comparisons (samples with MSAA)
  uint64_t pixelsWritten = 0;  // depth comparisons that won
  // Counters of one algorithm only (spans, active edges, ...), in print order.
  std::vector<std::pair<std::string, uint64_t>> extra;
};

}  // namespace zrender
