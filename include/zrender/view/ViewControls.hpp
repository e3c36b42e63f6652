#pragma once

#include <optional>
#include <string>

#include "zrender/scene/ShadingMode.hpp"
#include "zrender/view/ViewKeys.hpp"

namespace zrender {

// What the viewer shows: the settings a frame is rendered with and where the camera is on its
// orbit (OrbitCamera turns these into a Camera).
struct ViewState {
  std::string algorithm = "zbuffer";
  ShadingMode shading = ShadingMode::Normal;
  int msaa = 1;  // 1 or 4
  bool cull = true;
  double azimuth = 0.0;    // degrees about the up axis through the target, from the start
  double elevation = 0.0;  // degrees above the plane through the target normal to up
  int zoomSteps = 0;       // the eye's distance is the start's times 1.25^zoomSteps
  bool paused = false;
};

// What a key press asks of the viewer beyond the new state.
enum class ViewEffect {
  Camera,    // only the camera moved (or the orbit paused): nothing to rebuild
  Renderer,  // another algorithm: a new Renderer
  Scene,     // shading, MSAA or culling: a new Scene, then a new Renderer
  Save,      // write the current frame
  Quit
};

struct ViewChange {
  ViewEffect effect;
  std::string says;  // what changed, in words ("algorithm scanline", "tilt 10 degrees")
};

// The viewer's keys and orbit as a plain state machine, with no window: press() applies a key,
// advance() moves the orbit with time (docs/design.md, The viewer).
class ViewControls {
 public:
  static constexpr double kOrbitDegreesPerSecond = 30.0;
  static constexpr double kTiltStep = 10.0;      // degrees per W or S
  static constexpr double kTurnStep = 15.0;      // degrees per A or D
  static constexpr double kMaxElevation = 85.0;  // degrees: W and S stop here, short of up
  static constexpr int kMaxZoomSteps = 12;       // 1.25^12: about 14.6 times nearer or farther

  explicit ViewControls(const ViewState& start) : state_(start) {}

  // Applies a key; nullopt for a code no key of viewKeys() has.
  std::optional<ViewChange> press(int code);
  ViewChange press(const ViewKey& key);
  // Moves the orbit on by `seconds` at kOrbitDegreesPerSecond, unless paused.
  void advance(double seconds);

  const ViewState& state() const { return state_; }

 private:
  ViewState state_;
};

}  // namespace zrender
