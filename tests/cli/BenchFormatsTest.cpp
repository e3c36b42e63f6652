// The files a bench is written as for CI tools (docs/bench.md, Formats): markdown appended to a
// step summary, CSV, JUnit XML, github-action-benchmark's JSON and the chart (SVG, PNG); each
// holds the results file's numbers.

#include <gtest/gtest.h>
#include <json/json.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/CommandLineRuns.hpp"
#include "support/TestImages.hpp"
#include "support/TestSupport.hpp"

namespace zrender {
namespace {

using test::kSquareObj;
using test::runProgram;
using test::runZrender;
using test::settingsFor;
using test::TempDir;

size_t countOf(const std::string& text, const std::string& piece) {
  size_t n = 0;
  for (size_t at = text.find(piece); at != std::string::npos; at = text.find(piece, at + 1)) ++n;
  return n;
}

Json::Value readJson(const std::string& path) {
  std::ifstream in(path);
  Json::Value v;
  in >> v;
  return v;
}

std::string fixed4(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.4f", v);
  return buf;
}

struct Square {
  TempDir dir;
  Square() {
    dir.write("sq.obj", kSquareObj);
    dir.write("settings.json", settingsFor("sq.obj"));
  }
};

TEST(BenchFormats, MarkdownIsAppendedAndDashIsStdout) {
  Square s;
  const std::string summary = s.dir.write("summary.md", "# Earlier step\n");
  for (int i = 0; i < 2; ++i) {
    const auto r = runZrender(
        {"bench", "sq", "--alg", "zbuffer,octree", "--repeat", "1", "--markdown", summary},
        s.dir.path);
    ASSERT_EQ(r.status, 0) << r.err;
  }
  const std::string md = test::readFile(summary);
  EXPECT_EQ(md.rfind("# Earlier step\n", 0), 0u) << md;
  EXPECT_EQ(countOf(md, "| sq | 32x32 | octree |"), 2u) << md;
  EXPECT_EQ(countOf(md, "| sq | 32x32 | scanline |"), 0u) << md;  // --alg chose the two
  const auto dash = runZrender({"bench", "sq", "--repeat", "1", "--markdown", "-"}, s.dir.path);
  ASSERT_EQ(dash.status, 0) << dash.err;
  EXPECT_EQ(countOf(dash.out, "| scene | size | algorithm |"), 1u) << dash.out;
  EXPECT_FALSE(std::ifstream(s.dir.file("-")).good());
}

TEST(BenchFormats, CsvJunitAndActionJsonHoldTheResultsNumbers) {
  Square s;
  const auto r = runZrender(
      {"bench", "sq", "--repeat", "3", "--json", s.dir.file("r.json"), "--csv", s.dir.file("r.csv"),
       "--junit", s.dir.file("r.xml"), "--benchmark-action", s.dir.file("a.json")},
      s.dir.path);
  ASSERT_EQ(r.status, 0) << r.err;
  const Json::Value run = readJson(s.dir.file("r.json"));
  const Json::Value& cells = run["cells"];

  std::istringstream csv(test::readFile(s.dir.file("r.csv")));
  std::string header, line;
  std::getline(csv, header);
  EXPECT_EQ(header.rfind("scene,algorithm,width,height,msaa,shading,faces,threads,frames,"
                         "frame_median_ms,",
                         0),
            0u)
      << header;
  for (const Json::Value& c : cells) {
    ASSERT_TRUE(std::getline(csv, line));
    const std::string start = "sq," + c["algorithm"].asString() + ",32,32,1,normal,2,1,3," +
                              fixed4(c["frame_ms"]["median"].asDouble()) + "," +
                              fixed4(c["frame_ms"]["mad"].asDouble()) + "," +
                              fixed4(c["frame_ms"]["min"].asDouble()) + ",";
    EXPECT_EQ(line.rfind(start, 0), 0u) << line << "\nnot starting with " << start;
    EXPECT_EQ(line.substr(line.size() - 8), ",,,,,,,\r") << line;  // no baseline: columns empty
  }
  EXPECT_FALSE(std::getline(csv, line));

  // JUnit: well-formed (Python's parser), a test case per cell, its time the median in seconds.
  const std::string junit = test::readFile(s.dir.file("r.xml"));
  const auto parsed =
      runProgram({"/usr/bin/python3", "-c",
                  "import sys, xml.etree.ElementTree as ET\n"
                  "root = ET.parse(sys.argv[1]).getroot()\n"
                  "for c in root.iter('testcase'): print(c.get('name'), c.get('time'))\n",
                  s.dir.file("r.xml")});
  ASSERT_EQ(parsed.status, 0) << parsed.err;
  std::string expected;
  for (const Json::Value& c : cells) {
    char time[64];
    std::snprintf(time, sizeof time, "%.6f", c["frame_ms"]["median"].asDouble() / 1000);
    expected += "sq/" + c["algorithm"].asString() + "/32x32/msaa1/normal " + time + "\n";
  }
  EXPECT_EQ(parsed.out, expected);
  EXPECT_NE(junit.find("tests=\"5\" failures=\"0\""), std::string::npos) << junit;

  const Json::Value action = readJson(s.dir.file("a.json"));
  ASSERT_EQ(action.size(), cells.size());
  for (Json::ArrayIndex i = 0; i < cells.size(); ++i) {
    EXPECT_EQ(action[i]["name"].asString(),
              "sq/" + cells[i]["algorithm"].asString() + "/32x32/msaa1/normal");
    EXPECT_EQ(action[i]["unit"].asString(), "ms");
    EXPECT_DOUBLE_EQ(action[i]["value"].asDouble(), cells[i]["frame_ms"]["median"].asDouble());
  }
}

// The SVG chart: a group per algorithm, a bar per cell whose top is on one logarithmic axis
// shared by every scene, ticks labelled, and the baseline's medians as marks.
TEST(BenchFormats, TheChartHasOneLogAxisForAllScenes) {
  Square s;
  // A second scene, larger, so that the two scenes' times differ.
  const std::string camera = R"("eye": [0, 0, 2], "project": [90, 0, 0.1, 10])";
  s.dir.write("settings.json", R"({"sq": {"path": "sq.obj", "width": 32, "height": 32, )" + camera +
                                   R"(}, "big": {"path": "sq.obj", "width": 512, )" +
                                   R"("height": 512, )" + camera + "}}");
  const auto base = runZrender(
      {"bench", "sq", "big", "--repeat", "3", "--json", s.dir.file("b.json")}, s.dir.path);
  ASSERT_EQ(base.status, 0) << base.err << test::readFile(s.dir.file("settings.json"));
  const auto r = runZrender({"bench-report", s.dir.file("b.json"), "--baseline",
                             s.dir.file("b.json"), "--chart", s.dir.file("c.svg")},
                            s.dir.path);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string svg = test::readFile(s.dir.file("c.svg"));
  EXPECT_EQ(countOf(svg, "<g class=\"series\""), 5u);
  EXPECT_EQ(countOf(svg, "<rect class=\"bar\""), 10u);
  EXPECT_EQ(countOf(svg, "<line class=\"baseline\""), 10u);
  EXPECT_GE(countOf(svg, "class=\"tick-label\""), 2u);

  // Each bar's top y against its median: y = a - b log10(median) with one a and b for all.
  const Json::Value run = readJson(s.dir.file("b.json"));
  std::vector<double> tops, logs;
  size_t at = 0;
  for (const Json::Value& c : run["cells"]) {
    at = svg.find("<rect class=\"bar\"", at);
    ASSERT_NE(at, std::string::npos);
    const size_t y = svg.find(" y=\"", at) + 4;
    tops.push_back(std::stod(svg.substr(y)));
    logs.push_back(std::log10(c["frame_ms"]["median"].asDouble()));
    ++at;
  }
  // The bars are written by algorithm group (series), cells by scene: reorder the medians.
  std::vector<double> byAlgorithm;
  for (size_t a = 0; a < 5; ++a)
    for (size_t scene = 0; scene < 2; ++scene) byAlgorithm.push_back(logs[scene * 5 + a]);
  size_t far = 0;
  for (size_t i = 1; i < byAlgorithm.size(); ++i)
    if (std::abs(byAlgorithm[i] - byAlgorithm[0]) > std::abs(byAlgorithm[far] - byAlgorithm[0]))
      far = i;
  ASSERT_GT(std::abs(byAlgorithm[far] - byAlgorithm[0]), 0.01);
  const double slope = (tops[far] - tops[0]) / (byAlgorithm[far] - byAlgorithm[0]);
  EXPECT_LT(slope, 0);  // slower is higher
  for (size_t i = 0; i < tops.size(); ++i)
    EXPECT_NEAR(tops[i], tops[0] + slope * (byAlgorithm[i] - byAlgorithm[0]), 0.1) << i;

  const auto png = runZrender(
      {"bench-report", s.dir.file("b.json"), "--chart", s.dir.file("c.png")}, s.dir.path);
  ASSERT_EQ(png.status, 0) << png.err;
  EXPECT_FALSE(test::imread(s.dir.file("c.png")).empty());
  test::expectCleanError(
      runZrender({"bench-report", s.dir.file("b.json"), "--chart", s.dir.file("c.gif")},
                 s.dir.path),
      {"c.gif"});
}

// The HTML report: one page, nothing fetched, a section with a chart per scene, a row per cell,
// and the same bytes from bench-report (tools/bench-report-check.py opens it in Chromium).
TEST(BenchFormats, TheHtmlReportIsOneSelfContainedPage) {
  Square s;
  const auto r = runZrender({"bench", "sq", "--repeat", "2", "--json", s.dir.file("r.json"),
                             "--html", s.dir.file("r.html")},
                            s.dir.path);
  ASSERT_EQ(r.status, 0) << r.err;
  const std::string page = test::readFile(s.dir.file("r.html"));
  EXPECT_EQ(page.rfind("<!doctype html>", 0), 0u);
  EXPECT_EQ(countOf(page, "<svg class=\"chart\""), 1u);
  EXPECT_EQ(countOf(page, "<g class=\"series\""), 5u);
  EXPECT_EQ(countOf(page, "<img src=\"data:image/jpeg;base64,"), 1u);
  EXPECT_EQ(countOf(page, "<th scope=\"col\"><button"), 11u);  // no baseline, one thread
  EXPECT_EQ(countOf(page, "</tr>"), 5u + 1 + 5 + 1);  // counters: head and 5; cells: head and 5
  EXPECT_EQ(countOf(page, "http:") + countOf(page, "https:"), 0u) << "nothing to fetch";
  EXPECT_NE(page.find("all 5 were identical"), std::string::npos);
  const auto again = runZrender(
      {"bench-report", s.dir.file("r.json"), "--html", s.dir.file("again.html")}, s.dir.path);
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_EQ(test::readFile(s.dir.file("again.html")), page);
}

}  // namespace
}  // namespace zrender
