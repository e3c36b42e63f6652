// The viewer's figures (view/ViewFigures.hpp): what the overlay and the terminal say.

#include <gtest/gtest.h>

#include "zrender/view/ViewFigures.hpp"

namespace zrender {
namespace {

TEST(ViewFigures, TheStateTheTimesAndTheLastFramesCounters) {
  ViewState state;
  state.algorithm = "octree";
  state.shading = ShadingMode::Texture;
  state.msaa = 4;
  state.cull = false;
  state.paused = true;
  FrameTimes times;
  for (int i = 0; i < 3; ++i) times.add(2.0 + i, 40.0 * i);  // 2, 3, 4 ms every 40 ms
  RenderStats stats;
  stats.trianglesBackfaceCulled = 11;
  stats.trianglesClippedAway = 22;
  stats.trianglesHzbCulled = 33;
  stats.trianglesRasterized = 44;
  stats.octreeNodesCulled = 55;
  stats.octreeNodesVisited = 66;
  const auto lines = viewFigures(state, times, stats);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "octree  texture  msaa 4  cull off  paused");
  EXPECT_EQ(lines[1], "frame 3.00 ms (median of 3)  25.0 fps");
  EXPECT_EQ(lines[2], "culled: 11 back-facing, 22 clipped, 33 by the z-pyramid");
  EXPECT_EQ(lines[3], "drawn: 44 triangles; octree nodes: 55 of 66 culled");
}

}  // namespace
}  // namespace zrender
