#pragma once

#include "zrender/scene/Camera.hpp"
#include "zrender/scene/Scene.hpp"
#include "zrender/view/ViewControls.hpp"

namespace zrender {

// The viewer's camera: the scene's starting camera (makeCamera) with its eye moved on a sphere
// about the target, in world space. The eye's direction from the target is taken apart into an
// azimuth about the up axis and an elevation above the plane normal to it; a ViewState gives
// new ones and a distance, and the camera is rebuilt from eye, target and up exactly as
// makeCamera builds one (lookAt, perspective), so `zrender SCENE` given the same values renders
// the same frame.
class OrbitCamera {
 public:
  // With fit on, near and far hug the model's bounding sphere from each new eye, as fit does,
  // except those the scene keeps as given (SceneSettings::fitKeeps); otherwise they stay.
  OrbitCamera(const Camera& start, const Scene& scene);

  // The starting eye's elevation, degrees, the ViewState's first.
  double startElevation() const { return startElevation_; }
  Camera at(const ViewState& state) const;

 private:
  Camera start_;
  Vec3 up_;          // normalized
  Vec3 horizontal_;  // unit direction from the target to the starting eye, normal to up
  double distance_;  // from the target to the starting eye
  double startElevation_;
  bool hugNear_, hugFar_;
  Vec3 centre_;
  double radius_;
};

}  // namespace zrender
