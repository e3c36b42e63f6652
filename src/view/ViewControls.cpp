#include "zrender/view/ViewControls.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "zrender/visibility/VisibilityAlgorithm.hpp"

namespace zrender {

namespace {

// `format` with one %g: "elevation %g degrees".
std::string said(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

// Keeps an angle in [0, 360).
double wrap(double degrees) {
  const double a = std::fmod(degrees, 360.0);
  return a < 0.0 ? a + 360.0 : a;
}

}  // namespace

std::optional<ViewChange> ViewControls::press(int code) {
  const std::optional<ViewKey> key = viewKeyForCode(code);
  if (!key) return std::nullopt;
  return press(*key);
}

ViewChange ViewControls::press(const ViewKey& key) {
  const std::vector<std::string>& algorithms = algorithmNames();
  ViewState& s = state_;
  switch (key.action) {
    case ViewAction::NextAlgorithm: {
      const auto it = std::find(algorithms.begin(), algorithms.end(), s.algorithm);
      const size_t next = it == algorithms.end() ? 0 : size_t(it - algorithms.begin()) + 1;
      s.algorithm = algorithms[next % algorithms.size()];
      return {ViewEffect::Renderer, "algorithm " + s.algorithm};
    }
    case ViewAction::PickAlgorithm:
      s.algorithm = algorithms[size_t(key.rank) % algorithms.size()];
      return {ViewEffect::Renderer, "algorithm " + s.algorithm};
    case ViewAction::TiltUp:
      // Never past the limit by a key, but a start beyond it stays where it is.
      s.elevation = std::min(s.elevation + kTiltStep, std::max(s.elevation, kMaxElevation));
      return {ViewEffect::Camera, said("elevation %g degrees", s.elevation)};
    case ViewAction::TiltDown:
      s.elevation = std::max(s.elevation - kTiltStep, std::min(s.elevation, -kMaxElevation));
      return {ViewEffect::Camera, said("elevation %g degrees", s.elevation)};
    case ViewAction::TurnLeft:
      s.azimuth = wrap(s.azimuth - kTurnStep);
      return {ViewEffect::Camera, said("azimuth %g degrees", s.azimuth)};
    case ViewAction::TurnRight:
      s.azimuth = wrap(s.azimuth + kTurnStep);
      return {ViewEffect::Camera, said("azimuth %g degrees", s.azimuth)};
    case ViewAction::Closer:
      s.zoomSteps = std::max(s.zoomSteps - 1, -kMaxZoomSteps);
      return {ViewEffect::Camera, said("distance x%g", std::pow(1.25, s.zoomSteps))};
    case ViewAction::Farther:
      s.zoomSteps = std::min(s.zoomSteps + 1, kMaxZoomSteps);
      return {ViewEffect::Camera, said("distance x%g", std::pow(1.25, s.zoomSteps))};
    case ViewAction::TogglePause:
      s.paused = !s.paused;
      return {ViewEffect::Camera, s.paused ? "orbit paused" : "orbit resumed"};
    case ViewAction::ToggleMsaa:
      s.msaa = s.msaa == 4 ? 1 : 4;
      return {ViewEffect::Scene, "msaa " + std::to_string(s.msaa)};
    case ViewAction::NextShading: {
      const std::vector<std::string>& modes = shadingModeNames();
      const std::string name = shadingModeName(s.shading);
      const auto it = std::find(modes.begin(), modes.end(), name);
      const size_t next = it == modes.end() ? 0 : size_t(it - modes.begin()) + 1;
      s.shading = *parseShadingMode(modes[next % modes.size()]);
      return {ViewEffect::Scene, "shading " + shadingModeName(s.shading)};
    }
    case ViewAction::ToggleCulling:
      s.cull = !s.cull;
      return {ViewEffect::Scene, s.cull ? "culling on" : "culling off"};
    case ViewAction::SaveFrame:
      return {ViewEffect::Save, "save"};
    case ViewAction::Quit:
      return {ViewEffect::Quit, "quit"};
  }
  return {ViewEffect::Camera, ""};
}

void ViewControls::advance(double seconds) {
  if (!state_.paused) state_.azimuth = wrap(state_.azimuth + kOrbitDegreesPerSecond * seconds);
}

}  // namespace zrender
