#pragma once

// What libzrender_window.so (src/view/window/HighguiWindow.cpp) gives: OpenCV's highgui
// windows, loaded by `zrender view` only (view/ViewWindow.hpp; base/Plugin.hpp). Its factory:
// zrenderWindowPlugin.

#include <memory>
#include <string>

#include "zrender/view/ViewWindow.hpp"

namespace zrender {

class WindowPlugin {
 public:
  // A window titled `title` on the display of $DISPLAY; null with the reason in `error` when
  // there is no display or no GUI backend.
  virtual std::unique_ptr<ViewWindow> open(const std::string& title, std::string& error) = 0;

 protected:
  ~WindowPlugin() = default;
};

}  // namespace zrender
