#pragma once

#include <vector>

#include <opencv2/core.hpp>

namespace zrender {

// 4x4 matrices act on column vectors (p' = M * p), as in OpenGL.
using Mat4 = cv::Matx44d;
using Vec3 = cv::Vec3d;
using Vec4 = cv::Vec4d;

// Rotation of `degrees` about the (normalized) `axis` through the origin, right-hand rule.
Mat4 rotation(double degrees, const Vec3& axis);
Mat4 translation(const Vec3& offset);

// gluLookAt: world to view space; the camera looks down its -Z, `up` projects to +Y.
Mat4 lookAt(const Vec3& eye, const Vec3& target, const Vec3& up);

// gluPerspective: view to clip space; fovy in degrees, near and far positive distances.
Mat4 perspective(double fovyDegrees, double aspect, double near, double far);

// How `fit` frames a bounding sphere of `radius` (docs/design.md, Camera and transforms): the eye's
// distance from its centre so the sphere plus a 5% margin fills the smaller field of view, and near
// and far hugging it.
struct FitView {
  double distance, near, far;
};
FitView fitView(double radius, double fovyDegrees, double aspect);

// Near and far hugging a bounding sphere of `radius` (plus fit's 5% margin) whose centre lies
// `centreDepth` in front of the eye along the viewing direction (negative: behind). Near stays
// positive: at least 1/1000 of the larger of centreDepth and the radius, so an eye inside the
// sphere still gets a usable depth range.
FitView hugSphere(double centreDepth, double radius);

// Window position of a clip-space point with w > 0, in pixels: x right, y down, row 0 at the
// top (docs/design.md, Camera and transforms); z is window depth in 0..1, smaller is nearer.
// Inline: the transform runs it for every vertex of a frame.
inline Vec3 clipToWindow(const Vec4& clip, int width, int height) {
  const double invW = 1.0 / clip[3];
  const double xNdc = clip[0] * invW, yNdc = clip[1] * invW, zNdc = clip[2] * invW;
  return Vec3((xNdc + 1.0) * 0.5 * width, (1.0 - yNdc) * 0.5 * height, (zNdc + 1.0) * 0.5);
}

// An axis-aligned box, in the points' own space.
struct Box3 {
  Vec3 lo{0, 0, 0}, hi{0, 0, 0};
  Vec3 centre() const { return (lo + hi) * 0.5; }
};
// The box of `points`; all zero when there are none.
Box3 boundingBox(const std::vector<Vec3>& points);

inline Vec3 transformPoint(const Mat4& m, const Vec3& p) {
  const Vec4 r = m * Vec4(p[0], p[1], p[2], 1.0);
  return Vec3(r[0], r[1], r[2]);
}

// transformPoint() for a matrix whose last row is (0, 0, 0, 1), the same bits: the sums of
// cv::Matx's product, term by term from 0, without the fourth row.
inline Vec3 transformAffinePoint(const Mat4& m, const Vec3& p) {
  const auto row = [&](int i) {
    return 0.0 + m(i, 0) * p[0] + m(i, 1) * p[1] + m(i, 2) * p[2] + m(i, 3) * 1.0;
  };
  return Vec3(row(0), row(1), row(2));
}

inline Vec3 transformDirection(const Mat4& m, const Vec3& d) {
  return Vec3(m(0, 0) * d[0] + m(0, 1) * d[1] + m(0, 2) * d[2],
              m(1, 0) * d[0] + m(1, 1) * d[1] + m(1, 2) * d[2],
              m(2, 0) * d[0] + m(2, 1) * d[1] + m(2, 2) * d[2]);
}

}  // namespace zrender
