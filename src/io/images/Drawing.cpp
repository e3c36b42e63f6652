#include "zrender/io/images/Drawing.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <opencv2/imgproc.hpp>

namespace zrender {

namespace {

constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
constexpr int kMargin = 6;  // pixels between the overlay box's edge and the text

// The overlay text's layout, pixels: its scale, the tallest letter above and below the
// baseline, the height of a line and the width of the longest.
struct Layout {
  double scale;
  int ascent, descent, lineHeight, width;
};

Layout layout(const cv::Size& size, const std::vector<std::string>& lines) {
  // About 0.5 on a 600-pixel frame, then smaller until the longest line fits.
  double scale = std::clamp(0.5 * std::min(size.width, size.height) / 600.0, 0.3, 0.8);
  for (;;) {
    int width = 0, ascent = 0, descent = 0;
    for (const std::string& line : lines) {
      int baseline = 0;
      const cv::Size text = cv::getTextSize(line, kFont, scale, 1, &baseline);
      width = std::max(width, text.width);
      ascent = std::max(ascent, text.height);
      descent = std::max(descent, baseline);
    }
    if (width + 3 * kMargin <= size.width || scale <= 0.2)
      return {scale, ascent, descent, ascent + descent + kMargin / 2, width};
    scale *= 0.9;
  }
}

cv::Rect boxOf(const cv::Size& size, const std::vector<std::string>& lines) {
  const Layout l = layout(size, lines);
  const cv::Rect box(kMargin / 2, kMargin / 2, l.width + 2 * kMargin,
                     l.lineHeight * int(lines.size()) + kMargin);  // kMargin / 2 above and below
  return box & cv::Rect(0, 0, size.width, size.height);
}

cv::Mat overlaid(const cv::Mat& frame, const std::vector<std::string>& lines) {
  cv::Mat shown = frame.clone();
  const Layout l = layout(frame.size(), lines);
  const cv::Rect box = boxOf(frame.size(), lines);
  if (box.empty()) return shown;
  cv::Mat area = shown(box);
  area.convertTo(area, -1, 0.35);  // darkened, so white text reads on any model
  for (size_t i = 0; i < lines.size(); ++i) {
    const cv::Point origin(box.x + kMargin, box.y + kMargin / 2 + l.lineHeight * int(i) + l.ascent);
    cv::putText(shown, lines[i], origin, kFont, l.scale, cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
  }
  return shown;
}

cv::Mat sheetOf(const std::vector<cv::Mat>& frames) {
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

}  // namespace

PixelBox overlayBox(int width, int height, const std::vector<std::string>& lines) {
  const cv::Rect box = boxOf(cv::Size(width, height), lines);
  return PixelBox{box.x, box.y, box.width, box.height};
}

cv::Mat withOverlay(const cv::Mat& frame, const std::vector<std::string>& lines) {
  return overlaid(frame, lines);
}

cv::Mat contactSheet(const std::vector<cv::Mat>& frames) {
  return sheetOf(frames);
}

}  // namespace zrender
