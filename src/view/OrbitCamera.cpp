#include "zrender/view/OrbitCamera.hpp"

#include <algorithm>
#include <cmath>

namespace zrender {

namespace {

constexpr double kPi = 3.14159265358979323846;

double radians(double degrees) {
  return degrees * kPi / 180.0;
}

}  // namespace

OrbitCamera::OrbitCamera(const Camera& start, const Scene& scene) : start_(start) {
  up_ = cv::normalize(start.up);
  const Vec3 offset = start.eye - start.target;
  distance_ = cv::norm(offset);
  const double height = offset.dot(up_);
  const Vec3 across = offset - up_ * height;
  // validateScene refuses an up parallel to the viewing direction, so `across` is not zero;
  // the fallback only keeps a degenerate camera finite.
  horizontal_ = cv::norm(across) > 0.0 ? cv::normalize(across) : Vec3(up_[1], up_[2], up_[0]);
  startElevation_ = std::atan2(height, cv::norm(across)) * 180.0 / kPi;
  const SceneSettings& s = scene.settings;
  hugNear_ = s.fit && !s.fitKeeps.near;
  hugFar_ = s.fit && !s.fitKeeps.far;
  centre_ = scene.boundsCentre;
  radius_ = std::max(scene.boundsRadius, 1e-9);
}

Camera OrbitCamera::at(const ViewState& state) const {
  // The horizontal direction turned by the azimuth about up (right-hand rule), then raised.
  const double a = radians(state.azimuth), e = radians(state.elevation);
  const Vec3 side = up_.cross(horizontal_);
  const Vec3 around = horizontal_ * std::cos(a) + side * std::sin(a);
  const double distance = distance_ * std::pow(1.25, state.zoomSteps);
  Camera cam = start_;
  cam.eye = start_.target + (around * std::cos(e) + up_ * std::sin(e)) * distance;
  if (hugNear_ || hugFar_) {
    const double centreDepth = (centre_ - cam.eye).dot(cv::normalize(cam.target - cam.eye));
    const FitView hug = hugSphere(centreDepth, radius_);
    if (hugNear_) cam.near = hug.near;
    if (hugFar_) cam.far = hug.far;
  }
  cam.view = lookAt(cam.eye, cam.target, cam.up);
  cam.projection = perspective(cam.fovy, cam.aspect, cam.near, cam.far);
  return cam;
}

}  // namespace zrender
