// The viewer's loop (view/Viewer.hpp) with a window of the test's own: every frame is the
// renderer's image of the frame's camera with the overlay drawn on a copy, keys from the window
// and from --keys act one per frame, and the loop stops at quit, a closed window or --frames.

#include <gtest/gtest.h>

#include <chrono>
#include <deque>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "support/TestSupport.hpp"
#include "zrender/view/ViewFigures.hpp"
#include "zrender/view/Viewer.hpp"

namespace zrender {
namespace {

// Records what it is shown and answers waitKey from a queue of codes (then -1, or kClosed).
class RecordingWindow : public ViewWindow {
 public:
  explicit RecordingWindow(std::deque<int> codes, bool closeAtEnd = false)
      : codes_(std::move(codes)), closeAtEnd_(closeAtEnd) {}
  void show(const cv::Mat& image) override { shown.push_back(image.clone()); }
  int waitKey(int milliseconds) override {
    // As long as a window would wait, so that the orbit moves between frames as it does there.
    std::this_thread::sleep_for(std::chrono::milliseconds(milliseconds));
    if (codes_.empty()) return closeAtEnd_ ? kClosed : -1;
    const int code = codes_.front();
    codes_.pop_front();
    return code;
  }
  std::vector<cv::Mat> shown;

 private:
  std::deque<int> codes_;
  bool closeAtEnd_;
};

Scene cubeScene() {
  // A unit cube: some faces always face the orbiting eye, some never do.
  const std::vector<Vec3> corners = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                     {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  SceneSettings s = test::tinySettings(160);
  s.eye = Vec3(1.5, 2.0, 4.0);
  return makeScene(
      s, test::makeMesh(
             corners,
             {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}}));
}

std::vector<ViewKey> keys(const std::string& list) {
  return parseViewKeys(list, "--keys");
}

// A viewer of the cube with `options`, run to its end in a RecordingWindow answering `codes`.
struct ViewerRun {
  explicit ViewerRun(const ViewerOptions& options, std::deque<int> codes = {},
                     bool closeAtEnd = false)
      : window(std::move(codes), closeAtEnd), view(scene, options, out) {
    view.run(window);
  }
  const Scene scene = cubeScene();
  std::ostringstream out;
  RecordingWindow window;
  Viewer view;
};

// The frame the render command would make: a new renderer of the viewer's settings and camera.
cv::Mat renderedAlone(const Scene& loaded, const Viewer& view) {
  SceneSettings s = loaded.settings;
  s.shading = view.state().shading;
  s.msaa = view.state().msaa;
  s.cull = view.state().cull;
  const Scene scene = makeScene(s, loaded.mesh);
  Renderer renderer(scene, view.state().algorithm);
  renderer.renderFrame(view.lastCamera());
  return renderer.color().clone();
}

TEST(Viewer, KeysActOnePerFrameAndEveryFrameIsTheRenderersImage) {
  ViewerOptions options;
  options.scene = "cube";
  options.keys = keys("space,space,w,m,t,c,q");
  const ViewerRun run(options);
  const Viewer& view = run.view;
  const RecordingWindow& window = run.window;
  EXPECT_EQ(view.framesShown(), 7);  // the seventh key quits after the seventh frame
  ASSERT_EQ(window.shown.size(), 7u);
  const ViewState& s = view.state();
  EXPECT_EQ(s.algorithm, "interval");
  EXPECT_EQ(s.msaa, 4);
  EXPECT_EQ(s.shading, ShadingMode::Flat);
  EXPECT_FALSE(s.cull);
  const std::string text = run.out.str();
  for (const char* said : {"key 'space': algorithm scanline\n", "key 'space': algorithm interval\n",
                           "key 'w': elevation ", "key 'm': msaa 4\n", "key 't': shading flat\n",
                           "key 'c': culling off\n", "key 'q': quit\n",
                           "zrender view: interval  flat  msaa 4  cull off | frame "})
    EXPECT_NE(text.find(said), std::string::npos) << said << " in\n" << text;

  // The last frame is exactly what a renderer of its own makes for that camera; the window got
  // it with the overlay drawn inside the overlay's box only.
  const cv::Mat alone = renderedAlone(run.scene, view);
  EXPECT_EQ(cv::norm(view.lastFrame(), alone, cv::NORM_INF), 0.0);
  EXPECT_GT(cv::countNonZero(alone.reshape(1)), 100);
  const cv::Mat& shown = window.shown.back();
  const cv::Rect top(0, 0, shown.cols, shown.rows / 2),
      bottom(0, shown.rows / 2, shown.cols, shown.rows - shown.rows / 2);
  EXPECT_GT(cv::norm(shown(top), alone(top), cv::NORM_INF), 0.0) << "no overlay";
  EXPECT_EQ(cv::norm(shown(bottom), alone(bottom), cv::NORM_INF), 0.0);
}

TEST(Viewer, TheOrbitMovesTheCameraAndPausingStopsIt) {
  ViewerOptions options;
  options.keys = keys("p");
  options.frames = 6;
  const ViewerRun paused(options);
  EXPECT_EQ(paused.view.framesShown(), 6);
  EXPECT_TRUE(paused.view.state().paused);
  // Paused after the first frame: frames 2 to 6 show the same camera, so the same image below
  // the overlay (whose times change).
  const auto below = [](const cv::Mat& m) { return m.rowRange(m.rows / 2, m.rows); };
  const std::vector<cv::Mat>& still = paused.window.shown;
  for (size_t i = 2; i < still.size(); ++i)
    EXPECT_EQ(cv::norm(below(still[i]), below(still[1]), cv::NORM_INF), 0.0) << i;

  ViewerOptions moving;
  moving.frames = 3;
  const ViewerRun orbiting(moving);
  EXPECT_GT(orbiting.view.state().azimuth, 0.0);
  const std::vector<cv::Mat>& turned = orbiting.window.shown;
  EXPECT_GT(cv::norm(below(turned[2]), below(turned[1]), cv::NORM_INF), 0.0);
}

TEST(Viewer, WindowKeysActAndClosingTheWindowStops) {
  ViewerOptions options;
  options.collectSheet = true;
  const ViewerRun run(options, {-1, '5', 'x', 'T', -1}, true);
  const Viewer& view = run.view;
  const RecordingWindow& window = run.window;
  EXPECT_EQ(view.framesShown(), 6);
  EXPECT_EQ(view.state().algorithm, "octree");
  EXPECT_EQ(view.state().shading, ShadingMode::Flat);
  // The frames on screen when 5 and T were pressed, and the last.
  ASSERT_EQ(view.sheet().size(), 3u);
  EXPECT_EQ(cv::norm(view.sheet()[0], window.shown[1], cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(view.sheet()[2], window.shown[5], cv::NORM_INF), 0.0);
}

TEST(Viewer, KeysOfTheListComeEveryIntervalFrames) {
  ViewerOptions options;
  options.keys = keys("m,q");
  options.keyInterval = 4;
  const ViewerRun run(options);
  EXPECT_EQ(run.view.framesShown(), 8);
  EXPECT_EQ(run.view.state().msaa, 4);
}

}  // namespace
}  // namespace zrender
