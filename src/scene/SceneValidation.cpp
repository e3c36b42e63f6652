#include "zrender/scene/SceneValidation.hpp"

#include <cmath>

#include "zrender/scene/SettingsMessages.hpp"
#include "zrender/scene/Transforms.hpp"

namespace zrender {

bool isFiniteVec(const cv::Vec3d& v) {
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}

bool isUsableDirection(const cv::Vec3d& v) {
  const double length = cv::norm(v);
  return length > 0.0 && std::isfinite(length);
}

void checkSize(const std::string& where, const std::string& key, int value) {
  if (value < 1 || value > kMaxImageSize) {
    failKey(where, key,
            "expected an integer from 1 to " + std::to_string(kMaxImageSize) + ", got " +
                std::to_string(value));
  }
}

void checkProjection(const std::string& where, double fovy, double aspect, double near, double far,
                     bool nearBeforeFar) {
  if (!std::isfinite(fovy) || !std::isfinite(aspect) || !std::isfinite(near) ||
      !std::isfinite(far)) {
    failKey(where, "project",
            "expected 4 finite numbers [fovy, aspect, near, far], got [" + formatNumber(fovy) +
                ", " + formatNumber(aspect) + ", " + formatNumber(near) + ", " + formatNumber(far) +
                "]");
  }
  if (!(fovy > 0.0 && fovy < 180.0)) {
    failKey(where, "project",
            "fovy must be greater than 0 and less than 180 degrees, got " + formatNumber(fovy));
  }
  if (!(near > 0.0)) {
    failKey(where, "project", "near must be greater than 0, got " + formatNumber(near));
  }
  if (nearBeforeFar && !(far > near)) {
    failKey(where, "project",
            "far must be greater than near, got near " + formatNumber(near) + " and far " +
                formatNumber(far));
  }
}

void checkMsaa(const std::string& where, int msaa) {
  if (msaa != 1 && msaa != 4)
    failKey(where, "msaa", "expected 1 or 4, got " + std::to_string(msaa));
}

void checkFinite(const std::string& where, const std::string& key, const cv::Vec3d& v) {
  if (!isFiniteVec(v)) failKey(where, key, "expected 3 finite numbers, got " + formatVec(v));
}

void checkDirection(const std::string& where, const std::string& key, const cv::Vec3d& v) {
  checkFinite(where, key, v);
  if (!isUsableDirection(v)) {
    failKey(where, key, "must have a non-zero length, got " + formatVec(v));
  }
}

void checkGridCount(const std::string& where, const std::array<int, 3>& count) {
  for (int n : count) {
    if (n < 1 || n > kMaxInstances) {
      failKey(where, "grid.count",
              "expected 3 integers from 1 to " + std::to_string(kMaxInstances) + ", got [" +
                  std::to_string(count[0]) + ", " + std::to_string(count[1]) + ", " +
                  std::to_string(count[2]) + "]");
    }
  }
  // Each factor is at most 1e6, so the product fits in 64 bits.
  const long long total = static_cast<long long>(count[0]) * count[1] * count[2];
  if (total > kMaxInstances) {
    failKey(where, "grid.count",
            "at most " + std::to_string(kMaxInstances) + " instances in all, got " +
                std::to_string(count[0]) + " x " + std::to_string(count[1]) + " x " +
                std::to_string(count[2]) + " = " + std::to_string(total));
  }
}

void validateScene(const SceneSettings& scene, const std::string& sceneWhere,
                   const KeyOrigins& origins) {
  // The prefix for one key: the scene, and the options that set what that key's rule checks.
  const auto at = [&](const std::string& key) {
    const auto it = origins.find(key);
    return it == origins.end() ? sceneWhere : sceneWhere + " with " + it->second;
  };
  checkSize(at("width"), "width", scene.width);
  checkSize(at("height"), "height", scene.height);
  const FitKeeps& keep = scene.fitKeeps;
  const bool fitNear = scene.fit && !keep.near, fitFar = scene.fit && !keep.far;
  // With fit, a near or far of the file is checked even though fit replaces it; one the user
  // gave beside one fit supplies is checked against it in makeCamera.
  checkProjection(at("project"), scene.fovy, scene.aspect, scene.near, scene.far,
                  !scene.fit || keep.near == keep.far);
  {
    // Extreme finite values can still overflow the projection (2 far near / (near - far) once
    // far near passes 1e308, 1 / tan of a denormal fovy), and a non-finite camera would draw
    // nothing. fit replaces near and far by the ones that frame the model; fovy and aspect
    // are checked with those of a unit model (a bigger model's own overflow is makeCamera's to
    // report, naming the model).
    const double aspect =
        scene.aspect > 0.0 ? scene.aspect : double(scene.width) / double(scene.height);
    const FitView unit = fitView(1.0, scene.fovy, aspect);
    const double near = fitNear ? unit.near : scene.near, far = fitFar ? unit.far : scene.far;
    const Mat4 projection = perspective(scene.fovy, aspect, near, far);
    for (int i = 0; i < 16; ++i) {
      if (!std::isfinite(projection.val[i])) {
        failKey(at("project"), "project",
                "fovy " + formatNumber(scene.fovy) + ", aspect " + formatNumber(aspect) +
                    ", near " + formatNumber(scene.near) + " and far " + formatNumber(scene.far) +
                    " overflow the projection");
      }
    }
  }
  checkMsaa(at("msaa"), scene.msaa);
  if (!std::isfinite(scene.angle)) {
    failKey(at("angle"), "angle", "expected a finite number, got " + formatNumber(scene.angle));
  }
  checkDirection(at("axis"), "axis", scene.axis);
  checkDirection(at("up"), "up", scene.up);
  checkFinite(at("target"), "target", scene.target);
  for (int c : scene.background) {
    if (c < 0 || c > 255) {
      failKey(at("background"), "background",
              "expected 3 integers from 0 to 255, got [" + std::to_string(scene.background[0]) +
                  ", " + std::to_string(scene.background[1]) + ", " +
                  std::to_string(scene.background[2]) + "]");
    }
  }
  if (scene.grid) {
    checkGridCount(at("grid.count"), scene.grid->count);
    checkFinite(at("grid.spacing"), "grid.spacing", scene.grid->spacing);
  }

  // Without an eye, fit still keeps the default viewing direction, down -z (makeCamera puts
  // the eye at target + (0, 0, 1)), so up must not be parallel to it either.
  cv::Vec3d direction(0.0, 0.0, -1.0);
  std::string directionName = "the default viewing direction (no eye given) ";
  if (!scene.eye) {
    if (!scene.fit) failKey(at("eye"), "eye", "missing (required unless fit is on)");
  } else if (scene.fit && keep.eye && !keep.target) {
    // The target will be the model's centre: makeCamera checks the direction then.
    checkFinite(at("eye"), "eye", *scene.eye);
    return;
  } else {
    const cv::Vec3d eye = *scene.eye;
    checkFinite(at("eye"), "eye", eye);
    direction = scene.target - eye;
    directionName = "the viewing direction target - eye ";
    if (!isUsableDirection(direction)) {
      failKey(at("eye"), "eye",
              "must differ from target " + formatVec(scene.target) + ", got " + formatVec(eye));
    }
  }
  // lookAt needs a right vector up x direction; fit keeps both (docs/design.md, Camera and
  // transforms), so the rule holds with fit too. Unit vectors first: the cross product of raw large
  // vectors could overflow.
  const cv::Vec3d right = (direction / cv::norm(direction)).cross(scene.up / cv::norm(scene.up));
  const double sine = cv::norm(right);
  if (!(sine > 1e-9)) {
    failKey(at("up"), "up",
            "must not be parallel to " + directionName + formatVec(direction) + ", got " +
                formatVec(scene.up));
  }
}

}  // namespace zrender
