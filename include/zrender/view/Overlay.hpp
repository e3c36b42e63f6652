#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace zrender {

// Where withOverlay draws `lines` on a frame of `size` pixels: a box in the top-left corner,
// its text scaled down until the longest line fits the frame's width.
cv::Rect overlayBox(const cv::Size& size, const std::vector<std::string>& lines);

// A copy of `frame` (CV_8UC3) with `lines` written in white on a darkened box (overlayBox); the
// frame itself is left as the renderer made it.
cv::Mat withOverlay(const cv::Mat& frame, const std::vector<std::string>& lines);

}  // namespace zrender
