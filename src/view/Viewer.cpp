#include "zrender/view/Viewer.hpp"

#include <algorithm>
#include <cstdio>

#include "zrender/base/Clock.hpp"
#include "zrender/base/Error.hpp"
#include "zrender/io/images/Drawing.hpp"
#include "zrender/io/images/ImageOutput.hpp"
#include "zrender/view/FrameCommand.hpp"
#include "zrender/view/ViewFigures.hpp"

namespace zrender {

namespace {

constexpr double kFrameMs = 1000.0 / 60.0;  // at most 60 frames a second
constexpr double kPrintEveryMs = 1000.0;    // the figures on the terminal

ViewState startState(const Scene& scene, const std::string& algorithm) {
  ViewState s;
  s.algorithm = algorithm;
  s.shading = scene.settings.shading;
  s.msaa = scene.settings.msaa;
  s.cull = scene.settings.cull;
  return s;
}

}  // namespace

Viewer::Viewer(const Scene& loaded, const ViewerOptions& options, std::ostream& out)
    : options_(options),
      out_(out),
      loaded_(loaded),
      controls_(startState(loaded, options.algorithm)) {
  orbit_ = std::make_unique<OrbitCamera>(makeCamera(loaded_), loaded_);
  ViewState start = controls_.state();
  start.elevation = orbit_->startElevation();
  controls_ = ViewControls(start);
  rebuild(ViewEffect::Scene);
}

void Viewer::rebuild(ViewEffect effect) {
  const ViewState& s = controls_.state();
  if (effect == ViewEffect::Scene || !scene_) {
    renderer_.reset();                          // it refers to the scene
    scene_ = std::make_unique<Scene>(loaded_);  // shares the mesh and the texture
    scene_->settings.shading = s.shading;
    scene_->settings.msaa = s.msaa;
    scene_->settings.cull = s.cull;
  }
  renderer_ = std::make_unique<Renderer>(*scene_, s.algorithm, options_.threads);
}

std::string Viewer::lastFrameCommand() const {
  return frameCommand(options_.scene, options_.settingsFile, loaded_.settings, shownState_,
                      lastCamera_);
}

void Viewer::save() {
  // The first free SCENE-view-NNN.png in the working folder, where `zrender SCENE` writes.
  std::string name;
  std::error_code ec;
  for (int n = 1; name.empty() || std::filesystem::exists(name, ec); ++n) {
    char number[16];
    std::snprintf(number, sizeof number, "%03d", n);
    name = loaded_.settings.name + "-view-" + number + ".png";
  }
  try {
    writeImageAtomically(name, renderer_->color());
  } catch (const InputError& e) {  // a folder that cannot be written ends no session
    out_ << "zrender view: cannot save: " << e.what() << std::endl;
    return;
  }
  out_ << "zrender view: saved " << name << ", the image of: " << lastFrameCommand() << std::endl;
}

void Viewer::printFigures() {
  std::string line = "zrender view:";
  for (const std::string& figure : viewFigures(shownState_, times_, renderer_->stats()))
    line += (line.back() == ':' ? " " : " | ") + figure;
  out_ << line << std::endl;
}

void Viewer::run(ViewWindow& window) {
  size_t nextKey = 0;
  double lastFrameStart = nowMs(), lastPrint = lastFrameStart;
  cv::Mat shown;
  for (;;) {
    const double frameStart = nowMs();
    if (framesShown_ > 0) controls_.advance((frameStart - lastFrameStart) / 1000.0);
    lastFrameStart = frameStart;
    shownState_ = controls_.state();
    lastCamera_ = orbit_->at(shownState_);
    const FrameTimings timings = renderer_->renderFrame(lastCamera_);
    ++framesShown_;
    times_.add(timings.frameMs(), nowMs());
    shown = withOverlay(renderer_->color(), viewFigures(shownState_, times_, renderer_->stats()));
    window.show(shown);
    if (nowMs() - lastPrint >= kPrintEveryMs) {
      printFigures();
      lastPrint = nowMs();
    }
    if (options_.frames > 0 && framesShown_ >= options_.frames) break;

    const int wait = std::max(1, int(kFrameMs - (nowMs() - frameStart)));
    const int code = window.waitKey(wait);
    if (code == ViewWindow::kClosed) break;
    std::optional<ViewKey> key = viewKeyForCode(code);
    if (nextKey < options_.keys.size() && framesShown_ % options_.keyInterval == 0)
      key = options_.keys[nextKey++];
    if (!key) continue;
    const ViewChange change = controls_.press(*key);
    // The frame on screen when a key changed something (the last frame is added at the end).
    const bool changes = change.effect != ViewEffect::Quit && change.effect != ViewEffect::Save;
    if (options_.collectSheet && changes && int(sheet_.size()) < options_.sheetFrames - 1)
      sheet_.push_back(shown);
    out_ << "zrender view: key '" << key->name << "': " << change.says << std::endl;
    if (change.effect == ViewEffect::Quit) break;
    if (change.effect == ViewEffect::Save) save();
    if (change.effect == ViewEffect::Renderer || change.effect == ViewEffect::Scene) {
      rebuild(change.effect);
      times_ = FrameTimes();  // the figures are of the frames of the settings on screen
    }
  }
  if (options_.collectSheet) sheet_.push_back(shown);
  printFigures();
}

}  // namespace zrender
