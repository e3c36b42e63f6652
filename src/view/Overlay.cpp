#include "zrender/view/Overlay.hpp"

#include <algorithm>

#include <opencv2/imgproc.hpp>

namespace zrender {

namespace {

constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
constexpr int kMargin = 6;  // pixels between the box's edge and the text

// The text's layout, pixels: its scale, the tallest letter above and below the baseline, the
// height of a line and the width of the longest.
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

}  // namespace

cv::Rect overlayBox(const cv::Size& size, const std::vector<std::string>& lines) {
  const Layout l = layout(size, lines);
  const cv::Rect box(kMargin / 2, kMargin / 2, l.width + 2 * kMargin,
                     l.lineHeight * int(lines.size()) + kMargin);  // kMargin / 2 above and below
  return box & cv::Rect(0, 0, size.width, size.height);
}

cv::Mat withOverlay(const cv::Mat& frame, const std::vector<std::string>& lines) {
  cv::Mat shown = frame.clone();
  const Layout l = layout(frame.size(), lines);
  const cv::Rect box = overlayBox(frame.size(), lines);
  if (box.empty()) return shown;
  cv::Mat area = shown(box);
  area.convertTo(area, -1, 0.35);  // darkened, so white text reads on any model
  for (size_t i = 0; i < lines.size(); ++i) {
    const cv::Point origin(box.x + kMargin, box.y + kMargin / 2 + l.lineHeight * int(i) + l.ascent);
    cv::putText(shown, lines[i], origin, kFont, l.scale, cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
  }
  return shown;
}

}  // namespace zrender
