#include "zrender/io/Drawing.hpp"

#include <stdexcept>

#include "zrender/base/Plugin.hpp"
#include "zrender/io/DrawingPlugin.h"

namespace zrender {

namespace {

// The plugin's entry points, resolved once on first use and never changed afterwards.
struct DrawingPlugin {
  ZrenderDrawBarChartFn drawBarChart = nullptr;
  ZrenderOverlayBoxFn overlayBox = nullptr;
  ZrenderWithOverlayFn withOverlay = nullptr;
  ZrenderContactSheetFn contactSheet = nullptr;
};

const DrawingPlugin& drawingPlugin() {
  static const DrawingPlugin plugin = [] {
    std::string reason;
    void* handle = openPlugin("libzrender_drawing.so", reason);
    if (!handle)
      throw std::runtime_error("cannot load the drawing plugin libzrender_drawing.so: " + reason);
    const auto symbol = [handle](const char* name) { return pluginSymbol(handle, name); };
    DrawingPlugin p;
    p.drawBarChart = reinterpret_cast<ZrenderDrawBarChartFn>(symbol("zrenderDrawBarChart"));
    p.overlayBox = reinterpret_cast<ZrenderOverlayBoxFn>(symbol("zrenderOverlayBox"));
    p.withOverlay = reinterpret_cast<ZrenderWithOverlayFn>(symbol("zrenderWithOverlay"));
    p.contactSheet = reinterpret_cast<ZrenderContactSheetFn>(symbol("zrenderContactSheet"));
    if (!p.drawBarChart || !p.overlayBox || !p.withOverlay || !p.contactSheet)
      throw std::runtime_error("the drawing plugin libzrender_drawing.so is incomplete");
    return p;
  }();
  return plugin;
}

// Throws the plugin's message when `status` is not 0.
void check(int status, const char* error) {
  if (status != 0) throw std::runtime_error(std::string("drawing: ") + error);
}

}  // namespace

Image drawBarChart(const std::string& title, const std::vector<ChartGroup>& groups) {
  Image out;
  char error[512] = "";
  check(drawingPlugin().drawBarChart(&title, &groups, &out, error, sizeof error), error);
  return out;
}

PixelBox overlayBox(int width, int height, const std::vector<std::string>& lines) {
  PixelBox out;
  char error[512] = "";
  check(drawingPlugin().overlayBox(width, height, &lines, &out, error, sizeof error), error);
  return out;
}

Image withOverlay(const Image& frame, const std::vector<std::string>& lines) {
  Image out;
  char error[512] = "";
  check(drawingPlugin().withOverlay(&frame, &lines, &out, error, sizeof error), error);
  return out;
}

Image contactSheet(const std::vector<Image>& frames) {
  Image out;
  char error[512] = "";
  check(drawingPlugin().contactSheet(&frames, &out, error, sizeof error), error);
  return out;
}

}  // namespace zrender
