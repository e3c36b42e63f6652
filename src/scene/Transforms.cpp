#include "zrender/scene/Transforms.hpp"

#include <algorithm>
#include <cmath>

namespace zrender {

Mat4 rotation(double degrees, const Vec3& axis) {
  const Vec3 a = cv::normalize(axis);
  const double r = degrees * CV_PI / 180.0;
  const double c = std::cos(r), s = std::sin(r), t = 1.0 - c;
  const double x = a[0], y = a[1], z = a[2];
  // Rodrigues' formula, as glRotate.
  return Mat4(t * x * x + c, t * x * y - s * z, t * x * z + s * y, 0.0,  //
              t * x * y + s * z, t * y * y + c, t * y * z - s * x, 0.0,  //
              t * x * z - s * y, t * y * z + s * x, t * z * z + c, 0.0,  //
              0.0, 0.0, 0.0, 1.0);
}

Mat4 translation(const Vec3& o) {
  return Mat4(1, 0, 0, o[0], 0, 1, 0, o[1], 0, 0, 1, o[2], 0, 0, 0, 1);
}

Mat4 lookAt(const Vec3& eye, const Vec3& target, const Vec3& up) {
  const Vec3 f = cv::normalize(target - eye);
  const Vec3 s = cv::normalize(f.cross(up));
  const Vec3 u = s.cross(f);
  return Mat4(s[0], s[1], s[2], -s.dot(eye),    //
              u[0], u[1], u[2], -u.dot(eye),    //
              -f[0], -f[1], -f[2], f.dot(eye),  //
              0.0, 0.0, 0.0, 1.0);
}

Mat4 perspective(double fovyDegrees, double aspect, double near, double far) {
  const double f = 1.0 / std::tan(fovyDegrees * CV_PI / 360.0);
  return Mat4(f / aspect, 0.0, 0.0, 0.0,                                               //
              0.0, f, 0.0, 0.0,                                                        //
              0.0, 0.0, (far + near) / (near - far), 2.0 * far * near / (near - far),  //
              0.0, 0.0, -1.0, 0.0);
}

namespace {
constexpr double kFitMargin = 1.05;  // the sphere's radius plus 5%
}  // namespace

FitView fitView(double radius, double fovyDegrees, double aspect) {
  const double halfY = fovyDegrees * CV_PI / 360.0;
  const double halfX = std::atan(std::tan(halfY) * aspect);
  // At or beyond the margin's radius (the sine is at most 1), so hugSphere's near is
  // distance - r or distance / 1000.
  const double distance = radius * kFitMargin / std::sin(std::min(halfY, halfX));
  return hugSphere(distance, radius);
}

FitView hugSphere(double centreDepth, double radius) {
  const double r = radius * kFitMargin;
  const double near = std::max(centreDepth - r, std::max(centreDepth, r) * 1e-3);
  // A sphere wholly behind the eye shows nothing; any far beyond near will do.
  const double far = centreDepth + r > near ? centreDepth + r : 2.0 * near;
  return FitView{centreDepth, near, far};
}

Box3 boundingBox(const std::vector<Vec3>& points) {
  Box3 box;
  if (points.empty()) return box;
  box.lo = box.hi = points[0];
  for (const Vec3& p : points)
    for (int a = 0; a < 3; ++a)
      box.lo[a] = std::min(box.lo[a], p[a]), box.hi[a] = std::max(box.hi[a], p[a]);
  return box;
}

}  // namespace zrender
