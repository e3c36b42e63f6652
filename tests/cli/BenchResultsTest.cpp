// The bench's results file (`bench --json`, docs/bench.md, Results file): its schema, read back
// by `bench-report`, refused with the file and key when it is not one, and the exit statuses.

#include <gtest/gtest.h>
#include <json/json.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

#include "support/CommandLineRuns.hpp"
#include "support/TestSupport.hpp"
#include "zrender/visibility/VisibilityAlgorithm.hpp"

namespace zrender {
namespace {

using test::expectCleanError;
using test::kSquareObj;
using test::runProgram;
using test::runZrender;
using test::settingsFor;
using test::TempDir;

Json::Value readJson(const std::string& path) {
  std::ifstream in(path);
  Json::Value v;
  in >> v;
  return v;
}

// A bench of the square with --json FILE: its status.
int benchSquare(const TempDir& dir, const std::vector<std::string>& more) {
  dir.write("sq.obj", kSquareObj);
  dir.write("settings.json", settingsFor("sq.obj"));
  std::vector<std::string> args = {"bench", "sq", "--repeat", "3"};
  args.insert(args.end(), more.begin(), more.end());
  const auto r = runZrender(args, dir.path);
  EXPECT_EQ(r.status, 0) << r.err;
  return r.status;
}

TEST(BenchResults, TheFileFollowsItsSchemaAndHoldsEverySample) {
  TempDir dir;
  ASSERT_EQ(benchSquare(dir, {"--warmup", "2", "--json", dir.file("r.json")}), 0);
  // The schema in docs/, checked by an independent validator (Debian's python3-jsonschema).
  const std::string validate =
      "import json, sys, jsonschema\n"
      "schema = json.load(open(sys.argv[1]))\n"
      "jsonschema.Draft202012Validator.check_schema(schema)\n"
      "jsonschema.validate(json.load(open(sys.argv[2])), schema,\n"
      "                    cls=jsonschema.Draft202012Validator)\n";
  const auto v = runProgram({"/usr/bin/python3", "-c", validate,
                             std::string(ZRENDER_SOURCE_DIR) + "/docs/bench-results.schema.json",
                             dir.file("r.json")});
  EXPECT_EQ(v.status, 0) << v.err;

  const Json::Value j = readJson(dir.file("r.json"));
  EXPECT_EQ(j["schema"].asInt(), 1);
  EXPECT_EQ(j["zrender"]["version"].asString(), ZRENDER_VERSION);
  EXPECT_EQ(j["repeat"].asInt(), 3);
  EXPECT_EQ(j["warmup"].asInt(), 2);
  EXPECT_EQ(j["threads"].asInt(), 1);
  EXPECT_EQ(j["command"][1].asString(), "bench");
  // Built from this checkout: the commit is one of its history (HEAD when the build was made).
  if (!j["zrender"]["commit"].isNull()) {
    const auto type = runProgram(
        {"git", "-C", ZRENDER_SOURCE_DIR, "cat-file", "-t", j["zrender"]["commit"].asString()});
    EXPECT_EQ(type.out, "commit\n") << j["zrender"]["commit"] << type.err;
  }
  ASSERT_EQ(j["cells"].size(), algorithmNames().size());
  for (const Json::Value& c : j["cells"]) {
    ASSERT_EQ(c["frame_ms"]["samples"].size(), 3u) << c;
    std::vector<double> s;
    for (const Json::Value& sample : c["frame_ms"]["samples"]) s.push_back(sample.asDouble());
    std::sort(s.begin(), s.end());
    // The summary is the samples': median the middle one, min the first, MAD from the median.
    EXPECT_NEAR(c["frame_ms"]["median"].asDouble(), s[1], 1e-4);
    EXPECT_NEAR(c["frame_ms"]["min"].asDouble(), s[0], 1e-4);
    EXPECT_NEAR(c["frame_ms"]["mad"].asDouble(), std::min(s[1] - s[0], s[2] - s[1]), 2e-4);
    EXPECT_EQ(c["shading"].asString(), "normal");
    EXPECT_TRUE(c["identical"].asBool());
  }
}

TEST(BenchResults, ReportMakesTheSameTableFromTheFile) {
  TempDir dir;
  dir.write("sq.obj", kSquareObj);
  dir.write("settings.json", settingsFor("sq.obj"));
  const auto bench =
      runZrender({"bench", "sq", "--repeat", "2", "--json", dir.file("r.json")}, dir.path);
  ASSERT_EQ(bench.status, 0) << bench.err;
  const auto report = runZrender({"bench-report", dir.file("r.json")}, dir.path);
  ASSERT_EQ(report.status, 0) << report.err;
  EXPECT_EQ(report.out, bench.out);
  EXPECT_EQ(report.err, bench.err);
  // And the file read back and written again is the same file.
  const auto again =
      runZrender({"bench-report", dir.file("r.json"), "--json", dir.file("again.json")}, dir.path);
  ASSERT_EQ(again.status, 0) << again.err;
  EXPECT_EQ(test::readFile(dir.file("again.json")), test::readFile(dir.file("r.json")));
}

TEST(BenchResults, AFileThatIsNotOneNamesTheKey) {
  TempDir dir;
  ASSERT_EQ(benchSquare(dir, {"--json", dir.file("r.json")}), 0);
  const Json::Value good = readJson(dir.file("r.json"));
  auto reportOf = [&](const Json::Value& v) {
    dir.write("bad.json", Json::writeString(Json::StreamWriterBuilder(), v));
    return runZrender({"bench-report", dir.file("bad.json")}, dir.path);
  };
  Json::Value v = good;
  v["schema"] = 2;
  expectCleanError(reportOf(v), {"bad.json: schema: version 2", "(1)"});
  v = good;
  v.removeMember("cells");
  expectCleanError(reportOf(v), {"bad.json: (top).cells: missing"});
  v = good;
  v["cells"][1]["frame_ms"]["samples"][0] = -1;
  expectCleanError(reportOf(v), {"bad.json: cells[1].frame_ms.samples[0]: expected a time in ms"});
  v = good;
  v["cells"][2]["width"] = "wide";
  expectCleanError(reportOf(v), {"bad.json: cells[2].width: expected a whole number"});
  v = good;
  v["cells"][1] = good["cells"][0];
  expectCleanError(reportOf(v),
                   {"bad.json: cells[1]: a second cell sq/zbuffer/32x32/msaa1/normal"});
  dir.write("bad.json", "{\"schema\": 1,");
  expectCleanError(runZrender({"bench-report", dir.file("bad.json")}, dir.path),
                   {"bad.json: not a JSON file"});
  expectCleanError(runZrender({"bench-report", dir.file("none.json")}, dir.path),
                   {"none.json: cannot open file"});
}

// Exit statuses: 4 when an algorithm disagrees (also over 3), 2 for bad input, all before work.
TEST(BenchResults, ExitStatusesTellDisagreementFromBadInput) {
  TempDir dir;
  ASSERT_EQ(benchSquare(dir, {"--json", dir.file("r.json")}), 0);
  Json::Value v = readJson(dir.file("r.json"));
  v["cells"][3]["identical"] = false;
  dir.write("disagree.json", Json::writeString(Json::StreamWriterBuilder(), v));
  const auto r = runZrender({"bench-report", dir.file("disagree.json"), "--junit",
                             dir.file("j.xml"), "--markdown", dir.file("t.md")},
                            dir.path);
  EXPECT_EQ(r.status, 4) << r.err;
  EXPECT_NE(r.err.find("1 disagree with zbuffer"), std::string::npos) << r.err;
  EXPECT_NE(test::readFile(dir.file("j.xml")).find("type=\"disagreement\""), std::string::npos);
  EXPECT_NE(test::readFile(dir.file("t.md")).find("**NO**"), std::string::npos);

  // A baseline that cannot be read, or --max-slowdown without one: bad input before the bench.
  expectCleanError(runZrender({"bench", "sq", "--baseline", dir.file("none.json"), "--json",
                               dir.file("out.json")},
                              dir.path),
                   {"none.json: cannot open file"});
  EXPECT_FALSE(std::ifstream(dir.file("out.json")).good());
  expectCleanError(runZrender({"bench", "sq", "--max-slowdown", "5"}, dir.path),
                   {"--max-slowdown needs --baseline"});
  const auto help = runZrender({"bench", "--help"}, dir.path);
  EXPECT_NE(help.out.find("4 algorithms disagree"), std::string::npos) << help.out;
}

}  // namespace
}  // namespace zrender
