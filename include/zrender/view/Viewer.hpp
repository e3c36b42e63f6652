#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "zrender/render/Renderer.hpp"
#include "zrender/scene/Camera.hpp"
#include "zrender/scene/Scene.hpp"
#include "zrender/view/FrameTimes.hpp"
#include "zrender/view/OrbitCamera.hpp"
#include "zrender/view/ViewControls.hpp"
#include "zrender/view/ViewKeys.hpp"
#include "zrender/view/ViewWindow.hpp"

namespace zrender {

struct ViewerOptions {
  std::string scene;  // as the user typed it: for printed commands and saved names
  std::optional<std::filesystem::path> settingsFile;  // --settings, as typed
  std::string algorithm = "zbuffer";
  int threads = 1;            // per frame
  std::vector<ViewKey> keys;  // pressed one after every keyInterval frames
  int keyInterval = 1;
  int frames = 0;  // stop after this many; 0: until quit or the window is closed
  bool collectSheet = false;
  int sheetFrames = 16;  // at most this many collected
};

// `zrender view`'s loop (docs/design.md, The viewer): renders a frame with Renderer::renderFrame
// for the orbit's camera, shows a copy of Renderer::color() with the figures drawn on it, and
// applies the key pressed (from the window, or the next of options.keys). A key that changes the
// algorithm builds a new Renderer; one that changes shading, MSAA or culling also a new Scene
// from the loaded one's mesh and texture. Prints each key's effect, the figures once a second,
// and on stop the figures again.
class Viewer {
 public:
  // `loaded` as loadScene made it; the viewer keeps its own copy.
  Viewer(const Scene& loaded, const ViewerOptions& options, std::ostream& out);

  void run(ViewWindow& window);

  int framesShown() const { return framesShown_; }
  const ViewState& state() const { return shownState_; }  // of the last frame shown
  const Camera& lastCamera() const { return lastCamera_; }
  const cv::Mat& lastFrame() const { return renderer_->color(); }  // without the overlay
  // `zrender SCENE ...` rendering the last frame exactly (frameCommand).
  std::string lastFrameCommand() const;
  // With options.collectSheet: the frames on screen (overlay included) when a key changed
  // something (not enter or quit), at most options.sheetFrames - 1, and the last frame.
  const std::vector<cv::Mat>& sheet() const { return sheet_; }

 private:
  void rebuild(ViewEffect effect);
  void save();
  void printFigures();

  ViewerOptions options_;
  std::ostream& out_;
  Scene loaded_;
  std::unique_ptr<Scene> scene_;
  std::unique_ptr<Renderer> renderer_;
  ViewControls controls_;
  ViewState shownState_;
  std::unique_ptr<OrbitCamera> orbit_;
  FrameTimes times_;
  Camera lastCamera_;
  int framesShown_ = 0;
  std::vector<cv::Mat> sheet_;
};

}  // namespace zrender
