// The bench command (`zrender bench`, docs/design.md, Command line): the algorithms it runs, a
// table verified against the z-buffer, its files, and names and outputs checked before it
// runs.

#include <gtest/gtest.h>
#include <json/json.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "support/CommandLineRuns.hpp"
#include "support/TestImages.hpp"
#include "support/TestSupport.hpp"
#include "zrender/visibility/VisibilityAlgorithm.hpp"

namespace zrender {
namespace {

namespace fs = std::filesystem;
using test::expectCleanError;
using test::kSquareObj;
using test::runZrender;
using test::settingsFor;
using test::TempDir;

TEST(Bench, AlgsChoosesTheRowsAndNamesAreChecked) {
  TempDir dir;
  dir.write("sq.obj", kSquareObj);
  dir.write("settings.json", settingsFor("sq.obj"));  // not "bench": true, so named below
  const auto r = runZrender({"bench", "sq", "--algs", "octree,zbuffer", "--repeat", "1"}, dir.path);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("| sq | 32x32 | octree |"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("| sq | 32x32 | zbuffer |"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("| scanline |"), std::string::npos) << r.out;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 6) << r.out;  // title, blank, 2 + 2

  expectCleanError(runZrender({"bench", "sq", "--algs", "zbuffer,nope"}, dir.path),
                   {"command line: --algs: unknown algorithm 'nope'", "octree"});
  // An output that cannot be written fails before the bench runs: no table is printed.
  const auto unwritable = runZrender(
      {"bench", "sq", "--repeat", "1", "--markdown", "/proc/zrender-nope/t.md"}, dir.path);
  expectCleanError(unwritable, {"/proc/zrender-nope/t.md: cannot create folder"});
  EXPECT_EQ(unwritable.out, "");
  expectCleanError(runZrender({"bench"}, dir.path),
                   {"settings.json", "no scene has \"bench\": true"});
}

TEST(Bench, PrintsAVerifiedTableAndWritesItsFiles) {
  TempDir dir;
  dir.write("sq.obj", kSquareObj);
  dir.write("settings.json", settingsFor("sq.obj", R"(, "bench": true)"));
  const auto r = runZrender({"bench", "--repeat", "2", "--markdown", dir.file("t.md"), "--json",
                             dir.file("t.json"), "--chart", dir.file("c.png")},
                            dir.path);
  ASSERT_EQ(r.status, 0) << r.err;
  for (const auto& name : algorithmNames())
    EXPECT_NE(r.out.find("| sq | 32x32 | " + name + " |"), std::string::npos) << name;
  EXPECT_EQ(r.out.find("**NO**"), std::string::npos);
  EXPECT_NE(r.err.find("all identical to zbuffer"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir.file("t.md")));
  EXPECT_FALSE(test::imread(dir.file("c.png")).empty());
  std::ifstream json(dir.file("t.json"));
  Json::Value results;
  json >> results;
  const Json::Value& rows = results["cells"];
  ASSERT_EQ(rows.size(), algorithmNames().size());
  EXPECT_TRUE(rows[0]["identical"].asBool());
  // The algorithm's own work (visibility) apart from the shading that every algorithm shares;
  // raster is their sum, each a median of its own, so only their order holds.
  EXPECT_NE(r.out.find("| visibility ms | raster ms | frame ms |"), std::string::npos) << r.out;
  for (const Json::Value& row : rows) {
    ASSERT_TRUE(row.isMember("visibility_ms") && row.isMember("shade_ms")) << row;
    EXPECT_LE(row["visibility_ms"]["median"].asDouble(),
              row["raster_ms"]["median"].asDouble() + 0.0011);
  }
}

}  // namespace
}  // namespace zrender
