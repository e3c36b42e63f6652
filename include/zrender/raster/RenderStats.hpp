#pragma once

#include <algorithm>
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
  // Counters of one algorithm only (spans, active edges, ...), in print order; those named
  // max_... are maxima over the frame, the others totals.
  std::vector<std::pair<std::string, uint64_t>> extra;

  // Adds the counters of another part of the frame (a band drawn by another thread): the
  // extra ones by name (maxima by their maximum), new names after the others in their order.
  RenderStats& operator+=(const RenderStats& o) {
    trianglesBackfaceCulled += o.trianglesBackfaceCulled;
    trianglesClippedAway += o.trianglesClippedAway;
    trianglesDegenerate += o.trianglesDegenerate;
    trianglesRasterized += o.trianglesRasterized;
    trianglesHzbCulled += o.trianglesHzbCulled;
    octreeNodesVisited += o.octreeNodesVisited;
    octreeNodesCulled += o.octreeNodesCulled;
    pixelsTested += o.pixelsTested;
    pixelsWritten += o.pixelsWritten;
    for (const auto& counter : o.extra) {
      const std::string& name = counter.first;
      auto it =
          std::find_if(extra.begin(), extra.end(), [&](const auto& e) { return e.first == name; });
      if (it == extra.end())
        extra.push_back(counter);
      else if (name.rfind("max_", 0) == 0)
        it->second = std::max(it->second, counter.second);
      else
        it->second += counter.second;
    }
    return *this;
  }
};

}  // namespace zrender
