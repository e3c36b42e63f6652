#include "zrender/Camera.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "zrender/Error.hpp"

namespace zrender {

Camera makeCamera(const Scene& scene) {
  const SceneSettings& s = scene.settings;
  Camera cam;
  cam.width = s.width;
  cam.height = s.height;
  cam.fovy = s.fovy;
  cam.aspect = s.aspect > 0.0 ? s.aspect : double(s.width) / double(s.height);
  cam.near = s.near;
  cam.far = s.far;
  cam.up = s.up;
  cam.target = s.target;
  cam.eye = s.eye ? *s.eye : s.target + Vec3(0, 0, 1);

  if (s.fit) {
    const Vec3 dir = cv::normalize(cam.target - cam.eye);
    const FitView fit = fitView(std::max(scene.boundsRadius, 1e-9), s.fovy, cam.aspect);
    cam.target = scene.boundsCentre;
    cam.eye = cam.target - dir * fit.distance;
    cam.near = fit.near;
    cam.far = fit.far;
  }
  cam.view = lookAt(cam.eye, cam.target, cam.up);
  cam.projection = perspective(cam.fovy, cam.aspect, cam.near, cam.far);
  // validateScene keeps a camera given in full finite; fit can still overflow on a model of
  // huge coordinates (1e300: the radius squared, or far * near, is infinite), and a NaN camera
  // would silently draw nothing.
  for (int i = 0; i < 16; ++i) {
    if (!std::isfinite(cam.view.val[i]) || !std::isfinite(cam.projection.val[i])) {
      char radius[32];
      std::snprintf(radius, sizeof radius, "%g", scene.boundsRadius);
      throw InputError(s.modelPath.string() + ": cannot frame the model: its bounding sphere " +
                       "(radius " + radius + ") overflows the camera");
    }
  }
  return cam;
}

Camera turntableCamera(const Camera& camera, double degrees) {
  Camera turned = camera;
  turned.view = camera.view * translation(camera.target) * rotation(degrees, camera.up) *
                translation(-camera.target);
  return turned;
}

}  // namespace zrender
