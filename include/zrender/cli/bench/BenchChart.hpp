#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "zrender/cli/bench/BenchComparison.hpp"
#include "zrender/cli/bench/BenchResults.hpp"

namespace zrender {

// A chart as shapes in pixels (y down), drawn as SVG or into an image alike.
struct ChartShape {
  enum class Kind { Box, Line, Text } kind = Kind::Box;
  double x = 0, y = 0, x2 = 0, y2 = 0;  // Box: corners; Line: ends; Text: the anchor point
  uint32_t rgb = 0;                     // 0xRRGGBB
  std::string text;                     // Text: what it says; Box: its tooltip
  double size = 12;                     // Text: font size, pixels
  enum class Align { Start, Middle, End } align = Align::Start;  // Text only
  std::string role;    // its class in SVG ("bar", "baseline", "tick", ...)
  std::string series;  // the algorithm it draws, "" for the axes: a <g> per series in SVG
};

struct ChartPicture {
  int width = 0, height = 0;
  std::string title;
  std::vector<ChartShape> shapes;
};

// An algorithm's color in every chart and page (0xRRGGBB): Okabe and Ito's palette, told apart
// with every kind of colour blindness.
uint32_t algorithmColor(const std::string& algorithm);

// The bench chart (docs/bench.md, Chart): a group per scene (and size, MSAA, shading), a bar
// per algorithm in its own color from a legend, on one logarithmic axis of frame ms shared by
// every group, with labelled ticks; a bar's whisker spans its samples from the fastest to the
// slowest; with a baseline, its median is a black mark across the bar.
ChartPicture benchChart(const BenchRun& run, const BenchComparison* comparison);

std::string chartSvg(const ChartPicture& chart);  // a standalone SVG document
cv::Mat chartImage(const ChartPicture& chart);    // 8-bit BGR

}  // namespace zrender
