#include "zrender/cli/bench/BenchChart.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include <opencv2/imgproc.hpp>

#include "zrender/cli/bench/BenchFormats.hpp"
#include "zrender/visibility/VisibilityAlgorithm.hpp"

namespace zrender {

namespace {

// Layout, pixels.
constexpr double kPlotLeft = 70, kPlotTop = 78, kPlotHeight = 300, kPlotBottom = 64,
                 kPlotRight = 24;
constexpr double kBarWidth = 22, kBarGap = 4, kGroupGap = 34;
constexpr uint32_t kInk = 0x202020, kGrid = 0xdddddd, kAxis = 0x606060;

}  // namespace

uint32_t algorithmColor(const std::string& algorithm) {
  static constexpr uint32_t palette[] = {0x0072b2, 0xe69f00, 0x009e73, 0xcc79a7, 0xd55e00};
  const std::vector<std::string>& names = algorithmNames();
  const auto it = std::find(names.begin(), names.end(), algorithm);
  const size_t i = size_t(it - names.begin());
  return i < sizeof palette / sizeof palette[0] ? palette[i] : 0x56b4e9;
}

namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string ms(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, v < 10 ? "%.2f ms" : "%.1f ms", v);
  return buf;
}

// A cell's group: every key field but the algorithm.
std::string groupOf(const BenchKey& k) {
  return k.scene + " " + std::to_string(k.width) + "x" + std::to_string(k.height) +
         (k.msaa > 1 ? " MSAA" + std::to_string(k.msaa) : "") +
         (k.shading != "normal" ? " " + k.shading : "");
}

ChartShape box(double x, double y, double x2, double y2, uint32_t rgb, std::string role,
               std::string series = "", std::string tip = "") {
  ChartShape s;
  s.kind = ChartShape::Kind::Box;
  s.x = x, s.y = y, s.x2 = x2, s.y2 = y2, s.rgb = rgb;
  s.role = std::move(role), s.series = std::move(series), s.text = std::move(tip);
  return s;
}

ChartShape line(double x, double y, double x2, double y2, uint32_t rgb, std::string role,
                std::string series = "") {
  ChartShape s = box(x, y, x2, y2, rgb, std::move(role), std::move(series));
  s.kind = ChartShape::Kind::Line;
  return s;
}

ChartShape text(double x, double y, std::string what, double size, ChartShape::Align align,
                std::string role, uint32_t rgb = kInk, std::string series = "") {
  ChartShape s;
  s.kind = ChartShape::Kind::Text;
  s.x = x, s.y = y, s.rgb = rgb, s.text = std::move(what), s.size = size, s.align = align;
  s.role = std::move(role), s.series = std::move(series);
  return s;
}

}  // namespace

ChartPicture benchChart(const BenchRun& run, const BenchComparison* comparison) {
  ChartPicture chart;
  chart.title = "zrender bench: median frame ms per algorithm (log scale)";
  // The groups and the algorithms, in the run's order.
  std::vector<std::string> groups, algorithms;
  for (const BenchCell& c : run.cells) {
    if (std::find(groups.begin(), groups.end(), groupOf(c.key)) == groups.end())
      groups.push_back(groupOf(c.key));
    if (std::find(algorithms.begin(), algorithms.end(), c.key.algorithm) == algorithms.end())
      algorithms.push_back(c.key.algorithm);
  }
  // One axis for all: from the decade below the fastest sample to the one above the slowest.
  double lo = 0, hi = 0;
  auto include = [&](double v) {
    if (!(v > 0)) return;
    lo = lo > 0 ? std::min(lo, v) : v;
    hi = std::max(hi, v);
  };
  for (const BenchCell& c : run.cells)
    for (double v : c.frame.samples) include(v);
  if (comparison)
    for (const CellComparison& c : comparison->cells) include(c.baselineMs);
  if (!(lo > 0)) lo = hi = 1;
  const double lowDecade = std::floor(std::log10(lo));
  double highDecade = std::ceil(std::log10(hi));
  if (highDecade <= lowDecade) highDecade = lowDecade + 1;
  const double bottom = kPlotTop + kPlotHeight;
  auto yOf = [&](double v) {
    const double l = std::log10(std::max(v, std::pow(10.0, lowDecade)));
    return bottom - kPlotHeight * (l - lowDecade) / (highDecade - lowDecade);
  };

  const double groupWidth = double(algorithms.size()) * (kBarWidth + kBarGap) - kBarGap;
  const double plotWidth = double(groups.size()) * (groupWidth + kGroupGap) + kGroupGap;
  chart.height = int(bottom + kPlotBottom);
  auto& shapes = chart.shapes;
  shapes.push_back(box(0, 0, 0, chart.height, 0xffffff, "background"));  // width set below
  shapes.push_back(text(kPlotLeft, 24, chart.title, 16, ChartShape::Align::Start, "title"));

  // The legend, one entry per algorithm, then the baseline's mark.
  double lx = kPlotLeft;
  for (const std::string& a : algorithms) {
    shapes.push_back(box(lx, 38, lx + 12, 50, algorithmColor(a), "legend", a));
    shapes.push_back(text(lx + 16, 49, a, 12, ChartShape::Align::Start, "legend", kInk, a));
    lx += 28 + 7.5 * double(a.size());
  }
  if (comparison) {
    shapes.push_back(line(lx, 44, lx + 14, 44, 0x000000, "legend"));
    shapes.push_back(text(lx + 18, 49, "baseline median", 12, ChartShape::Align::Start, "legend"));
  }

  // Wide enough for the plot, the title and the legend (text about 0.6 of its size per letter).
  chart.width = int(std::max({kPlotLeft + plotWidth + kPlotRight,
                              kPlotLeft + 0.6 * 16 * double(chart.title.size()) + kPlotRight,
                              lx + (comparison ? 130.0 : 0.0) + kPlotRight}));
  shapes.front().x2 = chart.width;

  // Ticks at 1, 2 and 5 of each decade, labelled, with a grid line across the plot.
  for (double d = lowDecade; d <= highDecade; ++d)
    for (double m : {1.0, 2.0, 5.0}) {
      const double v = m * std::pow(10.0, d);
      if (d == highDecade && m > 1) break;
      const double y = yOf(v);
      shapes.push_back(
          line(kPlotLeft, y, kPlotLeft + plotWidth, y, m == 1 ? 0xc0c0c0 : kGrid, "grid"));
      shapes.push_back(line(kPlotLeft - 5, y, kPlotLeft, y, kAxis, "tick"));
      shapes.push_back(
          text(kPlotLeft - 8, y + 4, number(v), 11, ChartShape::Align::End, "tick-label", kAxis));
    }
  shapes.push_back(line(kPlotLeft, kPlotTop, kPlotLeft, bottom, kAxis, "axis"));
  shapes.push_back(line(kPlotLeft, bottom, kPlotLeft + plotWidth, bottom, kAxis, "axis"));
  shapes.push_back(
      text(kPlotLeft - 8, kPlotTop - 10, "ms", 11, ChartShape::Align::End, "axis-label"));

  for (size_t g = 0; g < groups.size(); ++g) {
    const double x0 = kPlotLeft + kGroupGap + double(g) * (groupWidth + kGroupGap);
    shapes.push_back(
        text(x0 + groupWidth / 2, bottom + 20, groups[g], 12, ChartShape::Align::Middle, "group"));
    for (const BenchCell& c : run.cells) {
      if (groupOf(c.key) != groups[g]) continue;
      const size_t a = size_t(std::find(algorithms.begin(), algorithms.end(), c.key.algorithm) -
                              algorithms.begin());
      const double x = x0 + double(a) * (kBarWidth + kBarGap), mid = x + kBarWidth / 2;
      const std::string& alg = c.key.algorithm;
      std::string tip = c.key.text() + ": median " + ms(c.frame.median) + ", MAD " +
                        ms(c.frame.mad) + ", " + std::to_string(c.frame.samples.size()) + " frames";
      const CellComparison* cmp = comparison ? comparison->find(c.key) : nullptr;
      if (cmp) tip += "; baseline " + ms(cmp->baselineMs) + ", " + verdictName(cmp->verdict);
      shapes.push_back(
          box(x, yOf(c.frame.median), x + kBarWidth, bottom, algorithmColor(alg), "bar", alg, tip));
      const auto [fastest, slowest] =
          std::minmax_element(c.frame.samples.begin(), c.frame.samples.end());
      if (fastest != c.frame.samples.end()) {
        const double top = yOf(*slowest), low = yOf(*fastest);
        shapes.push_back(line(mid, top, mid, low, kInk, "spread", alg));
        shapes.push_back(line(mid - 4, top, mid + 4, top, kInk, "spread", alg));
        shapes.push_back(line(mid - 4, low, mid + 4, low, kInk, "spread", alg));
      }
      if (cmp) {
        const double y = yOf(cmp->baselineMs);
        shapes.push_back(line(x - 3, y, x + kBarWidth + 3, y, 0x000000, "baseline", alg));
      }
    }
  }
  return chart;
}

namespace {

std::string xml(const std::string& s) {
  return xmlEscaped(s);
}

std::string svgShape(const ChartShape& s) {
  std::ostringstream o;
  o.setf(std::ios::fixed);
  o.precision(1);
  const std::string cls = s.role.empty() ? "" : " class=\"" + xml(s.role) + "\"";
  switch (s.kind) {
    case ChartShape::Kind::Box:
      o << "<rect" << cls << " x=\"" << std::min(s.x, s.x2) << "\" y=\"" << std::min(s.y, s.y2)
        << "\" width=\"" << std::abs(s.x2 - s.x) << "\" height=\"" << std::abs(s.y2 - s.y)
        << "\" fill=\"" << hexColor(s.rgb) << "\"";
      if (s.text.empty()) return o.str() + "/>";
      return o.str() + "><title>" + xml(s.text) + "</title></rect>";
    case ChartShape::Kind::Line:
      o << "<line" << cls << " x1=\"" << s.x << "\" y1=\"" << s.y << "\" x2=\"" << s.x2
        << "\" y2=\"" << s.y2 << "\" stroke=\"" << hexColor(s.rgb) << "\"/>";
      return o.str();
    case ChartShape::Kind::Text:
      break;
  }
  const char* anchor = s.align == ChartShape::Align::Start    ? "start"
                       : s.align == ChartShape::Align::Middle ? "middle"
                                                              : "end";
  o << "<text" << cls << " x=\"" << s.x << "\" y=\"" << s.y << "\" font-size=\"" << s.size
    << "\" text-anchor=\"" << anchor << "\" fill=\"" << hexColor(s.rgb) << "\">" << xml(s.text)
    << "</text>";
  return o.str();
}

}  // namespace

std::string chartSvg(const ChartPicture& chart) {
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << chart.width << "\" height=\""
      << chart.height << "\" viewBox=\"0 0 " << chart.width << " " << chart.height
      << "\" role=\"img\" aria-labelledby=\"chart-title\" font-family=\"sans-serif\">\n";
  svg << "<title id=\"chart-title\">" << xml(chart.title) << "</title>\n";
  // The axes and labels first, then one group per algorithm, in the order they appear.
  std::vector<std::string> series;
  for (const ChartShape& s : chart.shapes) {
    if (s.series.empty())
      svg << svgShape(s) << "\n";
    else if (std::find(series.begin(), series.end(), s.series) == series.end())
      series.push_back(s.series);
  }
  for (const std::string& name : series) {
    svg << "<g class=\"series\" data-algorithm=\"" << xml(name) << "\">\n";
    for (const ChartShape& s : chart.shapes)
      if (s.series == name) svg << svgShape(s) << "\n";
    svg << "</g>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

cv::Mat chartImage(const ChartPicture& chart) {
  cv::Mat image(chart.height, chart.width, CV_8UC3, cv::Scalar(255, 255, 255));
  auto bgr = [](uint32_t rgb) {
    return cv::Scalar(rgb & 0xff, (rgb >> 8) & 0xff, (rgb >> 16) & 0xff);
  };
  auto at = [](double x, double y) { return cv::Point(int(std::lround(x)), int(std::lround(y))); };
  for (const ChartShape& s : chart.shapes) {
    switch (s.kind) {
      case ChartShape::Kind::Box:
        cv::rectangle(image, at(s.x, s.y), at(s.x2, s.y2) - cv::Point(1, 1), bgr(s.rgb),
                      cv::FILLED);
        break;
      case ChartShape::Kind::Line:
        cv::line(image, at(s.x, s.y), at(s.x2, s.y2), bgr(s.rgb), 1);
        break;
      case ChartShape::Kind::Text: {
        // Hershey's simplex font at `size` pixels: its capitals are about 22 units tall.
        const double scale = s.size / 30.0;
        int base = 0;
        const cv::Size extent = cv::getTextSize(s.text, cv::FONT_HERSHEY_SIMPLEX, scale, 1, &base);
        const double shift = s.align == ChartShape::Align::Start    ? 0
                             : s.align == ChartShape::Align::Middle ? extent.width / 2.0
                                                                    : double(extent.width);
        cv::putText(image, s.text, at(s.x - shift, s.y), cv::FONT_HERSHEY_SIMPLEX, scale,
                    bgr(s.rgb), 1, cv::LINE_AA);
        break;
      }
    }
  }
  return image;
}

}  // namespace zrender
