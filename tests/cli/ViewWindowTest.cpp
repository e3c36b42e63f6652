// The real window of `zrender view` (docs/design.md, The viewer) on a virtual display, driven as
// a person would: xdotool finds the window and presses keys, xwd takes a screenshot, and the
// screenshot shows the model, exactly as rendered, with the overlay in its corner.

#include <gtest/gtest.h>

#include <chrono>
#include <future>
#include <memory>
#include <string>
#include <thread>

#include "support/TestImages.hpp"
#include "support/TestSupport.hpp"
#include "support/VirtualDisplay.hpp"
#include "support/XwdImage.hpp"

namespace zrender {
namespace {

using test::runProgram;
using test::TempDir;

// Where `frame` lies in `shot`, judged by the bottom half of the frame (the overlay is at the
// top): the offset (a few pixels of window border at most) at which it matches exactly.
cv::Point findFrame(const cv::Mat& shot, const cv::Mat& frame) {
  const cv::Rect bottom(0, frame.rows / 2, frame.cols, frame.rows - frame.rows / 2);
  for (int dy = 0; dy <= 16; ++dy) {
    for (int dx = 0; dx <= 16; ++dx) {
      const cv::Rect at = bottom + cv::Point(dx, dy);
      if (at.br().x > shot.cols || at.br().y > shot.rows) continue;
      if (cv::norm(shot(at), frame(bottom), cv::NORM_INF) == 0.0) return {dx, dy};
    }
  }
  return {-1, -1};
}

TEST(ViewWindow, ShowsTheModelWithTheOverlayAndAnswersKeys) {
  auto display = std::make_unique<test::VirtualDisplay>();
  ASSERT_FALSE(display->name().empty()) << display->error();
  const test::Environment env = display->environment();
  TempDir out;
  auto view = std::async(std::launch::async, [&] {
    return test::runZrender({"view", "teapot", "--width", "320", "--height", "240", "--shading",
                             "phong", "--save-last", out.file("last.png")},
                            "", {60, 0}, env);
  });
  const auto xdotool = [&](const std::vector<std::string>& args) {
    std::vector<std::string> argv = {"timeout", "20", "xdotool"};
    argv.insert(argv.end(), args.begin(), args.end());
    return runProgram(argv, "", {}, env);
  };
  const auto found = xdotool({"search", "--sync", "--name", "^zrender view: teapot$"});
  const std::string window = found.out.substr(0, found.out.find('\n'));
  std::string shotPath = out.file("shot.xwd");
  if (found.status == 0 && !window.empty()) {
    // Pause the orbit, change the algorithm (the image stays the same: they all agree), and
    // give the window time to show the frames of both. The pauses between keys are a person's:
    // highgui keeps one key per wait for a key, so two keys within a frame would lose the first.
    const auto pause = [](int ms) { std::this_thread::sleep_for(std::chrono::milliseconds(ms)); };
    pause(1000);
    xdotool({"key", "--window", window, "p"});
    pause(500);
    xdotool({"key", "--window", window, "space"});
    pause(1500);
    runProgram({"xwd", "-id", window, "-silent", "-out", shotPath}, "", {}, env);
    xdotool({"key", "--window", window, "q"});
  } else {
    ADD_FAILURE() << "no window: " << found.out << found.err;
    display.reset();  // zrender, its display gone, exits
  }
  const test::RunResult r = view.get();
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* said :
       {"key 'p': orbit paused\n", "key 'space': algorithm scanline\n", "key 'q': quit\n"})
    EXPECT_NE(r.out.find(said), std::string::npos) << said << " in\n" << r.out;

  const cv::Mat shot = test::readXwd(shotPath), last = test::imread(out.file("last.png"));
  ASSERT_FALSE(shot.empty()) << "no screenshot";
  ASSERT_EQ(last.size(), cv::Size(320, 240));
  EXPECT_GT(cv::countNonZero(last.reshape(1)), 5000) << "no teapot";
  // The window holds the last frame, the very image saved, below the overlay...
  const cv::Point at = findFrame(shot, last);
  ASSERT_NE(at.x, -1) << "the frame is not in the screenshot";
  const cv::Mat shown = shot(cv::Rect(at, last.size()));
  // ...and the overlay in the top-left corner: darkened, with white text.
  cv::Mat diff;
  cv::absdiff(shown, last, diff);
  const cv::Rect corner(0, 0, last.cols, last.rows / 3);
  EXPECT_EQ(cv::countNonZero(diff.reshape(1)), cv::countNonZero(diff(corner).clone().reshape(1)))
      << "the screenshot differs from the frame outside the overlay";
  EXPECT_GT(cv::countNonZero(diff(corner).clone().reshape(1)), 100) << "no overlay";
  cv::Mat white;
  cv::inRange(shown(corner), cv::Scalar(200, 200, 200), cv::Scalar(255, 255, 255), white);
  EXPECT_GT(cv::countNonZero(white), 100) << "no overlay text";
}

}  // namespace
}  // namespace zrender
