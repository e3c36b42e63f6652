#include "zrender/view/ViewWindow.hpp"

#include <cstdlib>
#include <stdexcept>

#include "zrender/base/Error.hpp"
#include "zrender/base/Plugin.hpp"
#include "zrender/view/WindowPlugin.hpp"

namespace zrender {

std::unique_ptr<ViewWindow> openViewWindow(const std::string& title, const char* what) {
  const std::string prefix = std::string(what) + ": ";
  // Said before loading the plugin: highgui's start costs more than this whole check.
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
    throw InputError(prefix +
                     "no display: DISPLAY is not set (run it on a desktop, or under Xvfb: "
                     "xvfb-run zrender view ...)");
  WindowPlugin* plugin = nullptr;
  try {
    plugin = &loadPlugin<WindowPlugin>("libzrender_window.so", "zrenderWindowPlugin");
  } catch (const std::runtime_error& e) {
    throw InputError(prefix + "no GUI backend: " + e.what());
  }
  std::string error;
  std::unique_ptr<ViewWindow> window = plugin->open(title, error);
  if (!window) throw InputError(prefix + error);
  return window;
}

}  // namespace zrender
