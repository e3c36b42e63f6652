// The viewer's state machine (view/ViewControls.hpp): each key changes what it says and asks for
// what must be rebuilt; the orbit moves with time unless paused.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "zrender/view/ViewControls.hpp"

namespace zrender {
namespace {

ViewChange press(ViewControls& c, int code) {
  const auto change = c.press(code);
  EXPECT_TRUE(change.has_value()) << code;
  return change.value_or(ViewChange{ViewEffect::Camera, ""});
}

TEST(ViewControls, SpaceCyclesTheAlgorithmsAndDigitsPickOne) {
  ViewControls c{ViewState{}};
  const char* order[] = {"scanline", "interval", "hierarchical", "octree", "zbuffer"};
  for (const char* name : order) {
    const ViewChange change = press(c, ' ');
    EXPECT_EQ(change.effect, ViewEffect::Renderer);
    EXPECT_EQ(change.says, std::string("algorithm ") + name);
    EXPECT_EQ(c.state().algorithm, name);
  }
  EXPECT_EQ(press(c, '4').says, "algorithm hierarchical");
  EXPECT_EQ(press(c, '1').says, "algorithm zbuffer");
  EXPECT_EQ(press(c, '5').says, "algorithm octree");
}

TEST(ViewControls, WAndSTiltByTenDegreesUpToTheLimit) {
  ViewState start;
  start.elevation = 60.0;
  ViewControls c{start};
  const ViewChange up = press(c, 'w');
  EXPECT_EQ(up.effect, ViewEffect::Camera);
  EXPECT_EQ(up.says, "elevation 70 degrees");
  press(c, 'w');
  EXPECT_EQ(press(c, 'w').says, "elevation 85 degrees");  // not 90: up would be the view axis
  EXPECT_EQ(c.state().elevation, ViewControls::kMaxElevation);
  EXPECT_EQ(press(c, 's').says, "elevation 75 degrees");
  for (int i = 0; i < 20; ++i) press(c, 's');
  EXPECT_EQ(c.state().elevation, -ViewControls::kMaxElevation);
}

TEST(ViewControls, AAndDTurnAndTheAzimuthWraps) {
  ViewControls c{ViewState{}};
  EXPECT_EQ(press(c, 'a').says, "azimuth 345 degrees");
  press(c, 'd');
  EXPECT_EQ(press(c, 'd').says, "azimuth 15 degrees");
}

TEST(ViewControls, PlusAndMinusMoveCloserAndFartherWithinLimits) {
  ViewControls c{ViewState{}};
  EXPECT_EQ(press(c, '+').says, "distance x0.8");
  EXPECT_EQ(c.state().zoomSteps, -1);
  press(c, '=');
  EXPECT_EQ(c.state().zoomSteps, -2);
  for (int i = 0; i < 40; ++i) press(c, '-');
  EXPECT_EQ(c.state().zoomSteps, ViewControls::kMaxZoomSteps);
  for (int i = 0; i < 40; ++i) press(c, '+');
  EXPECT_EQ(c.state().zoomSteps, -ViewControls::kMaxZoomSteps);
}

TEST(ViewControls, MTogglesMsaaTCyclesShadingCTogglesCullingAndAskForANewScene) {
  ViewControls c{ViewState{}};
  ViewChange m = press(c, 'm');
  EXPECT_EQ(m.effect, ViewEffect::Scene);
  EXPECT_EQ(m.says, "msaa 4");
  EXPECT_EQ(press(c, 'm').says, "msaa 1");
  const char* modes[] = {"flat", "phong", "random", "texture", "id", "depth", "normal"};
  for (const char* mode : modes) {
    const ViewChange t = press(c, 't');
    EXPECT_EQ(t.effect, ViewEffect::Scene);
    EXPECT_EQ(t.says, std::string("shading ") + mode);
  }
  EXPECT_EQ(press(c, 'c').says, "culling off");
  EXPECT_FALSE(c.state().cull);
  EXPECT_EQ(press(c, 'c').says, "culling on");
}

TEST(ViewControls, TheOrbitMovesAtItsSpeedUnlessPaused) {
  ViewControls c{ViewState{}};
  c.advance(2.0);
  EXPECT_DOUBLE_EQ(c.state().azimuth, 2.0 * ViewControls::kOrbitDegreesPerSecond);
  EXPECT_EQ(press(c, 'p').says, "orbit paused");
  c.advance(5.0);
  EXPECT_DOUBLE_EQ(c.state().azimuth, 2.0 * ViewControls::kOrbitDegreesPerSecond);
  EXPECT_EQ(press(c, 'p').says, "orbit resumed");
  c.advance(12.0);  // 360 degrees more: the same place
  EXPECT_NEAR(c.state().azimuth, 2.0 * ViewControls::kOrbitDegreesPerSecond, 1e-9);
}

TEST(ViewControls, EnterSavesQAndEscQuitOtherKeysDoNothing) {
  ViewControls c{ViewState{}};
  EXPECT_EQ(press(c, 13).effect, ViewEffect::Save);
  EXPECT_EQ(press(c, 'q').effect, ViewEffect::Quit);
  EXPECT_EQ(press(c, 27).effect, ViewEffect::Quit);
  EXPECT_FALSE(c.press('x').has_value());
  EXPECT_FALSE(c.press(-1).has_value());
}

}  // namespace
}  // namespace zrender
