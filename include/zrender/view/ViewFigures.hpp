#pragma once

#include <string>
#include <vector>

#include "zrender/raster/RenderStats.hpp"
#include "zrender/view/FrameTimes.hpp"
#include "zrender/view/ViewControls.hpp"

namespace zrender {

// The viewer's figures, one line each: the algorithm, shading, MSAA, culling and whether the
// orbit is paused; the median frame time and the frames per second; the last frame's culling
// counters. The overlay draws these lines; the terminal gets them joined by " | ".
std::vector<std::string> viewFigures(const ViewState& state, const FrameTimes& times,
                                     const RenderStats& stats);

}  // namespace zrender
