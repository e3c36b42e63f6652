// libzrender_window.so: OpenCV's highgui window behind the C interface of WindowPlugin.h,
// loaded by `zrender view` only (include/zrender/view/ViewWindow.hpp says why).

#include <X11/Xlib.h>

#include <cstdlib>
#include <string>

#include <opencv2/core/mat.hpp>
#include <opencv2/highgui.hpp>

#include "zrender/base/Plugin.hpp"
#include "zrender/view/WindowPlugin.h"

using zrender::setPluginError;

extern "C" {

__attribute__((visibility("default"))) void* zrenderWindowOpen(const char* title, char* error,
                                                               size_t size) {
  // Qt aborts the process when it cannot reach the display, so the display is tried first.
  Display* display = XOpenDisplay(nullptr);
  if (!display) {
    const char* name = std::getenv("DISPLAY");
    setPluginError(error, size,
                   std::string("no display: cannot open display '") + (name ? name : "") + "'");
    return nullptr;
  }
  XCloseDisplay(display);
  try {
    cv::namedWindow(title, cv::WINDOW_AUTOSIZE | cv::WINDOW_GUI_NORMAL);
  } catch (const cv::Exception& e) {
    setPluginError(error, size, "no GUI backend: " + e.msg);
    return nullptr;
  }
  return new std::string(title);
}

// No exception crosses the C interface: a window highgui cannot draw in any more is a closed
// one, which the next waitKey reports.
__attribute__((visibility("default"))) void zrenderWindowShow(void* window, const cv::Mat* image) {
  try {
    cv::imshow(*static_cast<std::string*>(window), *image);
  } catch (const cv::Exception&) {
  }
}

__attribute__((visibility("default"))) int zrenderWindowWaitKey(void* window, int milliseconds) {
  try {
    const int key = cv::waitKeyEx(milliseconds);
    if (key != -1) return key;
    if (cv::getWindowProperty(*static_cast<std::string*>(window), cv::WND_PROP_VISIBLE) < 1)
      return -2;
  } catch (const cv::Exception&) {
    return -2;
  }
  return -1;
}

__attribute__((visibility("default"))) void zrenderWindowClose(void* window) {
  auto* name = static_cast<std::string*>(window);
  try {
    cv::destroyWindow(*name);
  } catch (const cv::Exception&) {
  }
  delete name;
}

}  // extern "C"
