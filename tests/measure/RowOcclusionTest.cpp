// The occlusion of the rows of a grid along the view (measureRowOcclusion): the samples each
// row covers alone and those it shows behind the rows in front of it.

#include <gtest/gtest.h>

#include <vector>

#include "support/TestSupport.hpp"
#include "zrender/measure/RowOcclusion.hpp"

namespace zrender {
namespace {

// A square facing the eye (which looks down -z from z = 2), repeated in three rows along z
// at -0.5, 0 and 0.5, and `columns` columns 1.5 apart along x.
Scene squareRows(int columns) {
  SceneSettings settings = test::tinySettings(48);
  settings.grid = Grid{{columns, 1, 3}, Vec3(1.5, 0.0, 0.5)};
  Warnings warnings;
  return makeScene(settings,
                   test::makeMesh({{-0.5, -0.5, 0}, {0.5, -0.5, 0}, {0.5, 0.5, 0}, {-0.5, 0.5, 0}},
                                  {{0, 1, 2, 3}}));
}

TEST(RowOcclusion, NearestRowFirstHidingTheSmallerRowsBehindIt) {
  const Scene scene = squareRows(1);
  const std::vector<RowOcclusion> rows = measureRowOcclusion(scene, makeCamera(scene));
  ASSERT_EQ(rows.size(), 3u);
  // The square at z = 0.5 is 1.5 from the eye: 1 / 3 of the 90-degree view's width there, so
  // 16 x 16 of the 48 x 48 samples.
  EXPECT_EQ(rows[0].offsetZ, 0.5);
  EXPECT_EQ(rows[0].samplesAlone, 16u * 16u);
  EXPECT_EQ(rows[0].samplesVisible, 16u * 16u);
  // The others look smaller from farther away and lie wholly behind it: at distance 2, 1 / 4
  // of the width (12 x 12 samples); at 2.5, 1 / 5 (window 19.2 to 28.8: 10 x 10 samples).
  EXPECT_EQ(rows[1].offsetZ, 0.0);
  EXPECT_EQ(rows[1].samplesAlone, 12u * 12u);
  EXPECT_EQ(rows[1].samplesVisible, 0u);
  EXPECT_EQ(rows[2].offsetZ, -0.5);
  EXPECT_EQ(rows[2].samplesAlone, 10u * 10u);
  EXPECT_EQ(rows[2].samplesVisible, 0u);
}

TEST(RowOcclusion, VisibleSamplesOfAllRowsAreTheCoveredSamples) {
  // Two columns 1.5 apart: each row behind shows a strip beside the squares in front of it.
  const Scene scene = squareRows(2);
  const std::vector<RowOcclusion> rows = measureRowOcclusion(scene, makeCamera(scene));
  ASSERT_EQ(rows.size(), 3u);
  const test::Rendered all = test::render(scene, "zbuffer");
  size_t visible = 0;
  for (const RowOcclusion& r : rows) {
    visible += r.samplesVisible;
    EXPECT_GT(r.samplesVisible, 0u);
    EXPECT_LE(r.samplesVisible, r.samplesAlone);
  }
  EXPECT_EQ(visible, test::coveredSamples(all.buffer));
  EXPECT_EQ(rows[0].samplesVisible, rows[0].samplesAlone);
  EXPECT_LT(rows[1].samplesVisible, rows[1].samplesAlone);
}

}  // namespace
}  // namespace zrender
