#pragma once

#include <ostream>
#include <string>
#include <vector>

#include <json/json.h>

#include "zrender/base/Error.hpp"
#include "zrender/base/Median.hpp"
#include "zrender/raster/RenderStats.hpp"
#include "zrender/render/Renderer.hpp"

namespace zrender {

// Prints each warning on one line, "zrender: warning: TEXT" (messageLine), and clears them.
void printWarnings(Warnings& warnings, std::ostream& err);

// The `stats` object (docs/design.md, Timings and JSON).
Json::Value statsToJson(const RenderStats& stats);

// One JSON object on one line, numbers with at most 3 decimals.
std::string toJsonLine(const Json::Value& value);

// The statistics in words, one line per counter, then the frame's times (--stats; with
// --repeat, the median of each).
void printStats(const RenderStats& stats, const FrameTimings& times, std::ostream& out);

}  // namespace zrender
