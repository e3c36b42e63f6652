#pragma once

// The viewer's window. OpenCV's highgui lives in a plugin (libzrender_window.so) loaded only by
// `zrender view`: on Debian it pulls in Qt and its libraries, which every other run would load
// at its start for nothing (as the codecs, io/ImageCodecs.hpp).

#include <memory>
#include <string>

#include <opencv2/core/mat.hpp>

namespace zrender {

class ViewWindow {
 public:
  static constexpr int kClosed = -2;  // waitKey: the user closed the window

  virtual ~ViewWindow() = default;
  virtual void show(const cv::Mat& image) = 0;  // 8-bit BGR
  // Lets the window run for up to `milliseconds`; the code of a key pressed meanwhile (see
  // ViewKey), -1 for none, or kClosed.
  virtual int waitKey(int milliseconds) = 0;
};

// A highgui window titled `title`, sized by the images shown. Throws InputError naming `what`
// ("view") when there is no display ($DISPLAY unset or unreachable) or no GUI backend.
std::unique_ptr<ViewWindow> openViewWindow(const std::string& title, const char* what);

}  // namespace zrender
