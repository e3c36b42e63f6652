#include "zrender/scene/Camera.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "zrender/base/Error.hpp"

namespace zrender {

namespace {

std::string formatVec(const Vec3& v) {
  char text[96];
  std::snprintf(text, sizeof text, "[%g, %g, %g]", v[0], v[1], v[2]);
  return text;
}

// fit (docs/design.md, Camera and transforms), leaving as they are the camera values that
// s.fitKeeps names: a missing eye is placed along the viewing direction at fit's distance from the
// target, a missing target is the model's centre, and a missing near or far hugs the model's
// bounding sphere as seen from the final eye.
void fitCamera(const Scene& scene, Camera& cam) {
  const SceneSettings& s = scene.settings;
  const FitKeeps& keep = s.fitKeeps;
  const FitView fit = fitView(std::max(scene.boundsRadius, 1e-9), s.fovy, cam.aspect);
  const std::string& model = s.modelPath.string();
  if (keep.eye && !keep.target) {
    // The eye given, the target fit's: the direction is known only now.
    cam.target = scene.boundsCentre;
    const Vec3 direction = cam.target - cam.eye;
    if (!(cv::norm(direction) > 0.0)) {
      throw InputError(model + ": --eye " + formatVec(cam.eye) +
                       " is the model's centre, which fit makes the target: give --target too");
    }
    if (!(cv::norm(cv::normalize(direction).cross(cv::normalize(cam.up))) > 1e-9)) {
      throw InputError(model + ": --up " + formatVec(cam.up) +
                       " is parallel to the direction from --eye to the model's centre " +
                       formatVec(direction));
    }
  } else if (!keep.eye) {
    const Vec3 direction = cv::normalize(cam.target - cam.eye);
    if (!keep.target) cam.target = scene.boundsCentre;
    cam.eye = cam.target - direction * fit.distance;
  }
  // Fit's own eye and target: fit's depths; otherwise hug the sphere from where the eye is.
  const FitView depths =
      !keep.eye && !keep.target
          ? fit
          : hugSphere((scene.boundsCentre - cam.eye).dot(cv::normalize(cam.target - cam.eye)),
                      std::max(scene.boundsRadius, 1e-9));
  if (!keep.near) cam.near = depths.near;
  if (!keep.far) cam.far = depths.far;
  if (!(cam.far > cam.near)) {
    char range[96];
    std::snprintf(range, sizeof range, "near %g and far %g", cam.near, cam.far);
    throw InputError(
        model + ": key 'project': far must be greater than near, got " + range +
        (keep.near ? " (far from fit: give --far too)" : " (near from fit: give --near too)"));
  }
}

}  // namespace

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
  if (s.fit) fitCamera(scene, cam);
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
