#pragma once

#include <cstddef>

#include "zrender/raster/RasterRules.hpp"

namespace zrender {

// Sets keys[0, count) to `key`, as std::fill does. Where the CPU's string stores write whole
// cache lines without reading them first (cpuFillsWithoutReading()), by `rep stosq`: rows
// cleared just before they are drawn are then not fetched from memory only to be overwritten
// (docs/performance.md, The z-buffer's clear).
void fillKeys(DepthKey* keys, size_t count, DepthKey key);

// The two ways, for the tests: std::fill, and `rep stosq` (any x86-64 CPU runs it).
void fillKeysPlain(DepthKey* keys, size_t count, DepthKey key);
void fillKeysByStrings(DepthKey* keys, size_t count, DepthKey key);

}  // namespace zrender
