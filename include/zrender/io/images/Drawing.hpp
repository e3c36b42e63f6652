#pragma once

// Images drawn with OpenCV's imgproc, in the process: the viewer's overlay and contact sheets
// (the bench's chart is cli/bench/BenchChart.hpp). Each throws cv::Exception when OpenCV does.

#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

namespace zrender {

// A rectangle of pixels: its top-left corner and its size.
struct PixelBox {
  int x = 0, y = 0, width = 0, height = 0;
};

// Where withOverlay draws `lines` on a frame of `width` x `height` pixels: a box in the top-left
// corner, its text scaled down until the longest line fits the frame's width.
PixelBox overlayBox(int width, int height, const std::vector<std::string>& lines);

// A copy of `frame` (8-bit BGR) with `lines` written in white on a darkened box (overlayBox);
// the frame itself is left as the renderer made it.
cv::Mat withOverlay(const cv::Mat& frame, const std::vector<std::string>& lines);

// Frames (8-bit BGR, all of the first one's size) tiled left to right, top to bottom in a
// square grid, each scaled to fit a sheet about 1800 pixels wide and never enlarged: a
// turntable's frames (--contact-sheet) or the frames a viewer showed.
cv::Mat contactSheet(const std::vector<cv::Mat>& frames);

}  // namespace zrender
