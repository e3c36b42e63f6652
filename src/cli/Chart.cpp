#include "zrender/cli/Chart.hpp"

#include <algorithm>
#include <cstdio>

#include <opencv2/imgproc.hpp>

namespace zrender {

cv::Mat drawBarChart(const std::string& title, const std::vector<ChartGroup>& groups) {
  // Layout in pixels.
  const int barWidth = 70, barGap = 18, groupGap = 60, margin = 40;
  const int plotHeight = 320, top = 90, labelSpace = 70;
  int width = margin;
  for (const auto& g : groups)
    width += int(g.bars.size()) * (barWidth + barGap) - barGap + groupGap;
  width = std::max(width - groupGap + margin, 480);
  const int height = top + plotHeight + labelSpace + 20;
  cv::Mat image(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  const int font = cv::FONT_HERSHEY_SIMPLEX;
  cv::putText(image, title, cv::Point(margin, 36), font, 0.8, cv::Scalar(30, 30, 30), 2,
              cv::LINE_AA);

  // A fixed color per bar position (BGR), so an algorithm keeps its color across groups.
  const cv::Scalar palette[] = {{180, 119, 31}, {14, 127, 255},  {44, 160, 44},
                                {40, 39, 214},  {189, 103, 148}, {75, 86, 140}};
  const int baseline = top + plotHeight;
  int x = margin;
  for (const auto& g : groups) {
    double largest = 0.0;
    for (const auto& b : g.bars) largest = std::max(largest, b.value);
    const int groupStart = x;
    for (size_t i = 0; i < g.bars.size(); ++i) {
      const ChartBar& b = g.bars[i];
      const int h = largest > 0 ? int(plotHeight * b.value / largest + 0.5) : 0;
      const cv::Scalar color = palette[i % (sizeof palette / sizeof palette[0])];
      cv::rectangle(image, cv::Rect(x, baseline - h, barWidth, std::max(h, 1)), color, cv::FILLED);
      char text[32];
      if (b.part > 0.0 && largest > 0) {
        const int p = int(plotHeight * std::min(b.part, b.value) / largest + 0.5);
        cv::rectangle(image, cv::Rect(x, baseline - p, barWidth, std::max(p, 1)), color * 0.55,
                      cv::FILLED);
        std::snprintf(text, sizeof text, b.part < 10 ? "%.2f" : "%.1f", b.part);
        if (p >= 18)
          cv::putText(image, text, cv::Point(x + 2, baseline - p + 14), font, 0.42,
                      cv::Scalar(255, 255, 255), 1, cv::LINE_AA);
      }
      std::snprintf(text, sizeof text, b.value < 10 ? "%.2f" : "%.1f", b.value);
      cv::putText(image, text, cv::Point(x + 2, baseline - h - 8), font, 0.45,
                  cv::Scalar(30, 30, 30), 1, cv::LINE_AA);
      cv::putText(image, b.label, cv::Point(x, baseline + 20), font, 0.42, cv::Scalar(30, 30, 30),
                  1, cv::LINE_AA);
      x += barWidth + barGap;
    }
    cv::putText(image, g.caption, cv::Point(groupStart, baseline + 50), font, 0.55,
                cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
    x += groupGap - barGap;
  }
  cv::line(image, cv::Point(margin - 10, baseline), cv::Point(width - margin + 10, baseline),
           cv::Scalar(0, 0, 0), 1);
  return image;
}

}  // namespace zrender
