// libzrender_window.so: OpenCV's highgui windows behind view/WindowPlugin.hpp, loaded by
// `zrender view` only (include/zrender/view/ViewWindow.hpp says why).

#include <X11/Xlib.h>

#include <cstdlib>
#include <memory>
#include <string>

#include <opencv2/core/mat.hpp>
#include <opencv2/highgui.hpp>

#include "zrender/view/WindowPlugin.hpp"

namespace zrender {

namespace {

// A window highgui cannot draw in any more is a closed one, which the next waitKey reports:
// showing or closing it throws nothing.
class HighguiWindow : public ViewWindow {
 public:
  explicit HighguiWindow(std::string title) : title_(std::move(title)) {}
  ~HighguiWindow() override {
    try {
      cv::destroyWindow(title_);
    } catch (const cv::Exception&) {
    }
  }
  HighguiWindow(const HighguiWindow&) = delete;
  HighguiWindow& operator=(const HighguiWindow&) = delete;

  void show(const cv::Mat& image) override {
    try {
      cv::imshow(title_, image);
    } catch (const cv::Exception&) {
    }
  }
  int waitKey(int milliseconds) override {
    try {
      const int key = cv::waitKeyEx(milliseconds);
      if (key != -1) return key;
      if (cv::getWindowProperty(title_, cv::WND_PROP_VISIBLE) < 1) return kClosed;
    } catch (const cv::Exception&) {
      return kClosed;
    }
    return -1;
  }

 private:
  std::string title_;
};

class Highgui : public WindowPlugin {
 public:
  std::unique_ptr<ViewWindow> open(const std::string& title, std::string& error) override {
    // Qt aborts the process when it cannot reach the display, so the display is tried first.
    Display* display = XOpenDisplay(nullptr);
    if (!display) {
      const char* name = std::getenv("DISPLAY");
      error = std::string("no display: cannot open display '") + (name ? name : "") + "'";
      return nullptr;
    }
    XCloseDisplay(display);
    try {
      cv::namedWindow(title, cv::WINDOW_AUTOSIZE | cv::WINDOW_GUI_NORMAL);
    } catch (const cv::Exception& e) {
      error = "no GUI backend: " + e.msg;
      return nullptr;
    }
    return std::make_unique<HighguiWindow>(title);
  }
};

}  // namespace

}  // namespace zrender

extern "C" __attribute__((visibility("default"))) void* zrenderWindowPlugin() {
  static zrender::Highgui plugin;
  return static_cast<zrender::WindowPlugin*>(&plugin);
}
