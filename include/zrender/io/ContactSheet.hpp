#pragma once

#include <vector>

#include <opencv2/core.hpp>

namespace zrender {

// Frames (CV_8UC3, all of the first one's size) tiled left to right, top to bottom in a square
// grid, each scaled to fit a sheet about 1800 pixels wide and never enlarged: a turntable's
// frames (--contact-sheet) or the frames a viewer showed.
cv::Mat contactSheet(const std::vector<cv::Mat>& frames);

}  // namespace zrender
