#include "zrender/io/ContactSheet.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

namespace zrender {

cv::Mat contactSheet(const std::vector<cv::Mat>& frames) {
  const int n = int(frames.size());
  const int columns = int(std::ceil(std::sqrt(double(n))));
  const int rows = (n + columns - 1) / columns;
  const int cellWidth = std::min(frames[0].cols, 1800 / columns);
  const int cellHeight = std::max(1, frames[0].rows * cellWidth / frames[0].cols);
  cv::Mat sheet(rows * cellHeight, columns * cellWidth, CV_8UC3, cv::Scalar(0, 0, 0));
  for (int i = 0; i < n; ++i) {
    cv::Mat cell = sheet(
        cv::Rect((i % columns) * cellWidth, (i / columns) * cellHeight, cellWidth, cellHeight));
    cv::resize(frames[size_t(i)], cell, cell.size(), 0, 0, cv::INTER_AREA);
  }
  return sheet;
}

}  // namespace zrender
