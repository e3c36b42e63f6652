#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace zrender {

// One bar of a chart: a label under it and a value (milliseconds) written above it; `part` (a
// share of the value: the algorithm's own work in a frame) is drawn darker from the baseline,
// its value written inside.
struct ChartBar {
  std::string label;
  double value = 0.0;
  double part = 0.0;
};

// A group of bars sharing a caption (one scene of the bench table).
struct ChartGroup {
  std::string caption;
  std::vector<ChartBar> bars;
};

// Draws a grouped bar chart with OpenCV (CV_8UC3, white background). Each group is scaled to
// its own largest value, since scenes differ by orders of magnitude.
cv::Mat drawBarChart(const std::string& title, const std::vector<ChartGroup>& groups);

}  // namespace zrender
