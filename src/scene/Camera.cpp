#include "zrender/scene/Camera.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "zrender/base/Error.hpp"
#include "zrender/scene/SettingsMessages.hpp"

namespace zrender {

namespace {

constexpr double kPi = 3.14159265358979323846;

// fit (docs/design.md, Camera and transforms), leaving as they are the camera values that
// s.fitKeeps names: a missing eye is placed along the viewing direction at fit's distance from the
// target, a missing target is the model's centre, and a missing near or far hugs the model's
// bounding sphere as seen from the final eye.
void fitCamera(const Scene& scene, const SceneSettings& s, Camera& cam) {
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
  return makeCamera(scene, scene.settings);
}

Camera makeCamera(const Scene& scene, const SceneSettings& s) {
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
  if (s.fit) fitCamera(scene, s, cam);
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

Camera viewCamera(const Scene& scene, const Camera& base, const ViewSpec& view,
                  const std::string& where) {
  Camera cam = base;
  if (view.givesCamera()) {
    SceneSettings s = scene.settings;
    if (view.eye) s.eye = *view.eye;
    if (view.target) s.target = *view.target;
    if (view.up) s.up = *view.up;
    s.fitKeeps.eye = s.fitKeeps.eye || view.eye.has_value();
    s.fitKeeps.target = s.fitKeeps.target || view.target.has_value();
    // Where fit places the eye or the target, fitCamera checks what it makes.
    if (!s.fit || (s.fitKeeps.eye && s.fitKeeps.target)) {
      const Vec3 eye = s.eye ? *s.eye : s.target + Vec3(0, 0, 1);
      if (!(cv::norm(s.target - eye) > 0.0))
        throw InputError(where + ": the eye " + formatVec(eye) + " is the target");
      if (!(cv::norm(cv::normalize(s.target - eye).cross(cv::normalize(s.up))) > 1e-9)) {
        throw InputError(where + ": up " + formatVec(s.up) +
                         " is parallel to the viewing direction " + formatVec(s.target - eye));
      }
    }
    cam = makeCamera(scene, s);
  }
  if (view.azimuth != 0.0 || view.elevation != 0.0) {
    // The eye turns about the target; the view is composed with the inverse turn, which is the
    // world turned the other way (as a turntable turns the model). Elevation turns about the
    // camera's right axis (the view's first row), so that it raises the eye toward up even
    // past the pole, where lookAt would have no answer.
    const Vec3 right(cam.view(0, 0), cam.view(0, 1), cam.view(0, 2));
    const Mat4 raise = rotation(view.elevation, right), around = rotation(-view.azimuth, cam.up);
    // Multiplied left to right, as turntableCamera does: a turntable's frames are its views.
    Mat4 m = cam.view * translation(cam.target);
    if (view.elevation != 0.0) m = m * raise;
    if (view.azimuth != 0.0) m = m * around;
    cam.view = m * translation(-cam.target);
    // The eye and up in world space follow, by the inverse turn.
    const Mat4 inverse =
        translation(cam.target) * around.t() * raise.t() * translation(-cam.target);
    cam.eye = transformPoint(inverse, cam.eye);
    cam.up = transformDirection(inverse, cam.up);
    // Turned about a target that is not the model's centre, the eye is no longer at the depth
    // fit's near and far hug: they hug the sphere again from the new eye.
    const SceneSettings& s = scene.settings;
    if (s.fit && (!s.fitKeeps.near || !s.fitKeeps.far) && cam.target != scene.boundsCentre) {
      const double centreDepth =
          (scene.boundsCentre - cam.eye).dot(cv::normalize(cam.target - cam.eye));
      const FitView hug = hugSphere(centreDepth, std::max(scene.boundsRadius, 1e-9));
      if (!s.fitKeeps.near) cam.near = hug.near;
      if (!s.fitKeeps.far) cam.far = hug.far;
      cam.projection = perspective(cam.fovy, cam.aspect, cam.near, cam.far);
    }
  }
  if (view.zoom != 1.0) {
    const double half = std::atan(std::tan(cam.fovy * kPi / 360.0) / view.zoom);
    cam.fovy = half * 360.0 / kPi;
    cam.projection = perspective(cam.fovy, cam.aspect, cam.near, cam.far);
  }
  return cam;
}

}  // namespace zrender
