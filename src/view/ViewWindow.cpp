#include "zrender/view/ViewWindow.hpp"

#include <cstdlib>

#include "zrender/base/Error.hpp"
#include "zrender/base/Plugin.hpp"
#include "zrender/view/WindowPlugin.h"

namespace zrender {

namespace {

// The plugin's entry points.
struct WindowPlugin {
  ZrenderWindowOpenFn open = nullptr;
  ZrenderWindowShowFn show = nullptr;
  ZrenderWindowWaitKeyFn waitKey = nullptr;
  ZrenderWindowCloseFn close = nullptr;
};

class HighguiWindow : public ViewWindow {
 public:
  HighguiWindow(void* handle, const WindowPlugin& plugin) : handle_(handle), plugin_(plugin) {}
  ~HighguiWindow() override { plugin_.close(handle_); }
  HighguiWindow(const HighguiWindow&) = delete;
  HighguiWindow& operator=(const HighguiWindow&) = delete;

  void show(const cv::Mat& image) override { plugin_.show(handle_, &image); }
  int waitKey(int milliseconds) override { return plugin_.waitKey(handle_, milliseconds); }

 private:
  void* handle_;
  WindowPlugin plugin_;
};

}  // namespace

std::unique_ptr<ViewWindow> openViewWindow(const std::string& title, const char* what) {
  const std::string prefix = std::string(what) + ": ";
  // Said before loading the plugin: highgui's start costs more than this whole check.
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
    throw InputError(prefix +
                     "no display: DISPLAY is not set (run it on a desktop, or under Xvfb: "
                     "xvfb-run zrender view ...)");
  std::string reason;
  void* plugin = openPlugin("libzrender_window.so", reason);
  if (!plugin)
    throw InputError(prefix + "no GUI backend: cannot load libzrender_window.so: " + reason);
  WindowPlugin p;
  p.open = reinterpret_cast<ZrenderWindowOpenFn>(pluginSymbol(plugin, "zrenderWindowOpen"));
  p.show = reinterpret_cast<ZrenderWindowShowFn>(pluginSymbol(plugin, "zrenderWindowShow"));
  p.waitKey =
      reinterpret_cast<ZrenderWindowWaitKeyFn>(pluginSymbol(plugin, "zrenderWindowWaitKey"));
  p.close = reinterpret_cast<ZrenderWindowCloseFn>(pluginSymbol(plugin, "zrenderWindowClose"));
  if (!p.open || !p.show || !p.waitKey || !p.close)
    throw InputError(prefix + "no GUI backend: libzrender_window.so is incomplete");
  char error[512] = "";
  void* handle = p.open(title.c_str(), error, sizeof error);
  if (!handle) throw InputError(prefix + error);
  return std::make_unique<HighguiWindow>(handle, p);
}

}  // namespace zrender
