// The rows a scene's instances may cover (screenRows), which the hierarchical algorithm's
// threads cut into bands.

#include <gtest/gtest.h>

#include "support/TestSupport.hpp"
#include "zrender/transform/ScreenRows.hpp"

namespace zrender {
namespace {

// tinySettings: the plane z = 0 shows y in [-2, 2] over the image's rows, top to bottom, so
// y lands on sample row (1 - y / 2) / 2 * height.
TEST(ScreenRows, TheMeshBoxRowsWidenedByARow) {
  auto mesh = test::makeMesh({{-0.5, 0.1, 0}, {0.5, 0.1, 0}, {0, 0.9, 0}}, {{0, 1, 2}});
  const Scene scene = makeScene(test::tinySettings(16), mesh);
  // y 0.9 on row 4.4, y 0.1 on row 7.6: rows 4 to 7, and one more each way.
  const RowSpan rows = screenRows(scene, makeCamera(scene), 16);
  EXPECT_EQ(rows.begin, 3);
  EXPECT_EQ(rows.end, 9);
}

TEST(ScreenRows, EveryInstanceCounts) {
  auto mesh = test::makeMesh({{-0.5, 0.1, 0}, {0.5, 0.1, 0}, {0, 0.9, 0}}, {{0, 1, 2}});
  SceneSettings s = test::tinySettings(16);
  s.grid = Grid{{1, 2, 1}, {0.0, 2.0, 0.0}};  // copies at y - 1 and y + 1
  const Scene scene = makeScene(s, mesh);
  // The upper copy from row 0.4, the lower one to row 11.6 (y -0.9).
  const RowSpan rows = screenRows(scene, makeCamera(scene), 16);
  EXPECT_EQ(rows.begin, 0);
  EXPECT_EQ(rows.end, 13);
  // Rows in samples: twice as many with MSAA 4.
  const RowSpan samples = screenRows(scene, makeCamera(scene), 32);
  EXPECT_EQ(samples.begin, 0);
  EXPECT_EQ(samples.end, 25);
}

TEST(ScreenRows, ABoxThatReachesTheNearPlaneMayCoverAnyRow) {
  // The eye is at z = 2 and near is 0.1: z = 1.95 is in front of the near plane.
  auto mesh = test::makeMesh({{-0.5, 0.1, 0}, {0.5, 0.1, 1.95}, {0, 0.9, 0}}, {{0, 1, 2}});
  const Scene scene = makeScene(test::tinySettings(16), mesh);
  const RowSpan rows = screenRows(scene, makeCamera(scene), 16);
  EXPECT_EQ(rows.begin, 0);
  EXPECT_EQ(rows.end, 16);
}

}  // namespace
}  // namespace zrender
