// SurfaceSetup::setUpInto() for four triangles at once, in AVX2's four doubles: lane by lane
// the scalar set-up's operations in the same order (cv::Vec's sums from 0, its division as a
// product by the reciprocal; no fused multiply-adds: -ffp-contract=off), so the same bits
// (SurfaceSetupTest checks every face of the reference models). A face's set-up is a few
// hundred double operations; docs/performance.md, Shading, has what four at once save.

#include <immintrin.h>

#include "zrender/base/CpuFeatures.hpp"
#include "zrender/shading/SurfaceSetup.hpp"

namespace zrender {

namespace {

using D = __m256d;

// A vector of three coordinates, each one lane per face.
struct Vec3x4 {
  D x, y, z;
};

ZRENDER_AVX2 inline D add(D a, D b) {
  return _mm256_add_pd(a, b);
}
ZRENDER_AVX2 inline D sub(D a, D b) {
  return _mm256_sub_pd(a, b);
}
ZRENDER_AVX2 inline D mul(D a, D b) {
  return _mm256_mul_pd(a, b);
}
ZRENDER_AVX2 inline D negate(D a) {
  return _mm256_xor_pd(a, _mm256_set1_pd(-0.0));
}
ZRENDER_AVX2 inline D select(D mask, D ifTrue, D ifFalse) {
  return _mm256_blendv_pd(ifFalse, ifTrue, mask);
}
ZRENDER_AVX2 inline D load(const double lanes[4]) {
  return _mm256_load_pd(lanes);
}

ZRENDER_AVX2 inline Vec3x4 vec3(const double lanes[3][4]) {
  return {load(lanes[0]), load(lanes[1]), load(lanes[2])};
}
ZRENDER_AVX2 inline Vec3x4 minus(const Vec3x4& a, const Vec3x4& b) {
  return {sub(a.x, b.x), sub(a.y, b.y), sub(a.z, b.z)};
}
ZRENDER_AVX2 inline Vec3x4 negate(const Vec3x4& a) {
  return {negate(a.x), negate(a.y), negate(a.z)};
}
// cv::Vec3d::cross.
ZRENDER_AVX2 inline Vec3x4 cross(const Vec3x4& v, const Vec3x4& w) {
  return {sub(mul(v.y, w.z), mul(v.z, w.y)), sub(mul(v.z, w.x), mul(v.x, w.z)),
          sub(mul(v.x, w.y), mul(v.y, w.x))};
}
// cv::Vec3d::dot: a sum from 0.
ZRENDER_AVX2 inline D dot(const Vec3x4& a, const Vec3x4& b) {
  return add(add(add(_mm256_setzero_pd(), mul(a.x, b.x)), mul(a.y, b.y)), mul(a.z, b.z));
}

// The model-view matrices' top three rows, m[r][c] one lane per face.
struct Rows {
  alignas(32) double m[3][4][4];
  ZRENDER_AVX2 D at(int r, int c) const { return load(m[r][c]); }
  // transformAffinePoint: each row's sum from 0, the translation times 1.
  ZRENDER_AVX2 Vec3x4 point(const Vec3x4& p) const {
    D out[3];
    for (int r = 0; r < 3; ++r)
      out[r] = add(add(add(add(_mm256_setzero_pd(), mul(at(r, 0), p.x)), mul(at(r, 1), p.y)),
                       mul(at(r, 2), p.z)),
                   mul(at(r, 3), _mm256_set1_pd(1.0)));
    return {out[0], out[1], out[2]};
  }
  // transformDirection.
  ZRENDER_AVX2 Vec3x4 direction(const Vec3x4& d) const {
    D out[3];
    for (int r = 0; r < 3; ++r)
      out[r] = add(add(mul(at(r, 0), d.x), mul(at(r, 1), d.y)), mul(at(r, 2), d.z));
    return {out[0], out[1], out[2]};
  }
};

// safeNormalize: v times 1 / |v| (cv::norm's sum from 0), +Z where |v| is 0.
ZRENDER_AVX2 inline Vec3x4 safeNormalize(const Vec3x4& v) {
  const D zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
  const D length = _mm256_sqrt_pd(add(add(add(zero, mul(v.x, v.x)), mul(v.y, v.y)), mul(v.z, v.z)));
  const D positive = _mm256_cmp_pd(length, zero, _CMP_GT_OQ);
  const D inverse = _mm256_div_pd(one, length);
  return {select(positive, mul(v.x, inverse), zero), select(positive, mul(v.y, inverse), zero),
          select(positive, mul(v.z, inverse), one)};
}

// Lane `lane` of a vector.
ZRENDER_AVX2 inline double laneOf(D v, int lane) {
  alignas(32) double lanes[4];
  _mm256_store_pd(lanes, v);
  return lanes[lane];
}

// Four lanes rounded to float, in out[0, 4).
ZRENDER_AVX2 inline void toFloats(D v, float out[4]) {
  _mm_storeu_ps(out, _mm256_cvtpd_ps(v));
}

}  // namespace

ZRENDER_AVX2 void SurfaceSetup::setUpFourTriangles(const uint32_t faceIds[4],
                                                   SurfaceRecord* const records[4],
                                                   const uint32_t firstFans[4]) const {
  // The faces' inputs, one lane per face.
  Rows rows;
  alignas(32) double position[3][3][4], normal[3][3][4], uv[3][2][4], geometric[3][4];
  FaceSurface faces[4];
  for (int lane = 0; lane < 4; ++lane) {
    const FaceRef ref = scene_.locate(faceIds[lane]);
    const Mat4& mv = (*modelView_)[ref.instance];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) rows.m[r][c][lane] = mv(r, c);
    const CornerData* corners = corners_.data() + 3 * size_t(ref.meshFace);
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 3; ++k) {
        position[i][k][lane] = corners[i].position[k];
        normal[i][k][lane] = double(corners[i].normal[k]);
      }
      for (int k = 0; k < 2; ++k) uv[i][k][lane] = double(corners[i].uv[k]);
    }
    for (int k = 0; k < 3; ++k) geometric[k][lane] = double(faces_[ref.meshFace].geometric[k]);
    faces[lane] = faceFields(ref);
  }
  // The corners in view space, the normals turned to the eye's side in the lit modes.
  Vec3x4 p[3], n[3];
  for (int i = 0; i < 3; ++i) {
    p[i] = rows.point(vec3(position[i]));
    n[i] = safeNormalize(rows.direction(vec3(normal[i])));
  }
  const Vec3x4 toEye = negate(p[0]);
  if (mode_ != ShadingMode::Normal) {
    const D flip =
        _mm256_cmp_pd(dot(rows.direction(vec3(geometric)), toEye), _mm256_setzero_pd(), _CMP_LT_OQ);
    for (Vec3x4& v : n)
      v = {select(flip, negate(v.x), v.x), select(flip, negate(v.y), v.y),
           select(flip, negate(v.z), v.z)};
  }
  alignas(32) double origin[3][4];
  for (int lane = 0; lane < 4; ++lane) {
    placeOrigin(faces[lane],
                Vec3(laneOf(p[0].x, lane), laneOf(p[0].y, lane), laneOf(p[0].z, lane)));
    origin[0][lane] = rayOriginX_ + (faces[lane].originX + 0.5) * rayScaleX_;
    origin[1][lane] = rayOriginY_ - (faces[lane].originY + 0.5) * rayScaleY_;
    origin[2][lane] = -1.0;
  }

  // The fan's planes (setUpInto's loop with j = 1).
  const Vec3x4 e1 = minus(p[1], p[0]), e2 = minus(p[2], p[0]);
  const Vec3x4 vectors[3] = {cross(e2, e1), cross(e2, toEye), cross(toEye, e1)};
  const D zero = _mm256_setzero_pd();
  const int degenerate =
      _mm256_movemask_pd(_mm256_and_pd(_mm256_and_pd(_mm256_cmp_pd(vectors[0].x, zero, _CMP_EQ_OQ),
                                                     _mm256_cmp_pd(vectors[0].y, zero, _CMP_EQ_OQ)),
                                       _mm256_cmp_pd(vectors[0].z, zero, _CMP_EQ_OQ)));
  D planes[kSurfacePlanes][3];
  D largest = zero;
  const D magnitude = _mm256_castsi256_pd(_mm256_set1_epi64x(0x7FFFFFFFFFFFFFFF));
  for (int k = 0; k < 3; ++k) {
    planes[k][0] = mul(vectors[k].x, _mm256_set1_pd(rayScaleX_));
    planes[k][1] = mul(negate(vectors[k].y), _mm256_set1_pd(rayScaleY_));
    planes[k][2] = dot(vectors[k], vec3(origin));
    for (const D value : planes[k]) {  // std::max(largest, |value|)
      const D size = _mm256_and_pd(value, magnitude);
      largest = select(_mm256_cmp_pd(largest, size, _CMP_LT_OQ), size, largest);
    }
  }
  // The attributes at corners 0, 1, 2: the normal's x, y, z, then u, v.
  D attribute[5][3];
  for (int i = 0; i < 3; ++i) {
    attribute[0][i] = n[i].x;
    attribute[1][i] = n[i].y;
    attribute[2][i] = n[i].z;
    attribute[3][i] = load(uv[i][0]);
    attribute[4][i] = load(uv[i][1]);
  }
  for (int k = 0; k < 5; ++k)
    for (int c = 0; c < 3; ++c)
      planes[3 + k][c] = add(add(mul(attribute[k][0], planes[0][c]),
                                 mul(sub(attribute[k][1], attribute[k][0]), planes[1][c])),
                             mul(sub(attribute[k][2], attribute[k][0]), planes[2][c]));
  const D one = _mm256_set1_pd(1.0);
  const D sign =
      select(_mm256_cmp_pd(dot(p[0], vectors[0]), zero, _CMP_LT_OQ), _mm256_set1_pd(-1.0), one);
  const D usable = _mm256_and_pd(_mm256_cmp_pd(largest, zero, _CMP_GT_OQ),
                                 _mm256_cmp_pd(largest, _mm256_set1_pd(INFINITY), _CMP_LT_OQ));
  const D scale = mul(select(usable, _mm256_div_pd(one, largest), one), sign);

  // Into the records, lane by lane.
  float a[kSurfacePlanes][4], b[kSurfacePlanes][4], c[kSurfacePlanes][4];
  for (int k = 0; k < kSurfacePlanes; ++k) {
    toFloats(mul(planes[k][0], scale), a[k]);
    toFloats(mul(planes[k][1], scale), b[k]);
    toFloats(mul(planes[k][2], scale), c[k]);
  }
  float corner[5][3][4];
  for (int k = 0; k < 5; ++k)
    for (int i = 0; i < 3; ++i) toFloats(attribute[k][i], corner[k][i]);
  for (int lane = 0; lane < 4; ++lane) {
    SurfaceFan& fan = records[lane]->fan;
    for (int k = 0; k < kSurfacePlanes; ++k) {
      fan.a[k] = a[k][lane];
      fan.b[k] = b[k][lane];
      fan.c[k] = c[k][lane];
    }
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 3; ++k) fan.cornerNormal[i][k] = corner[k][i][lane];
      for (int k = 0; k < 2; ++k) fan.cornerUv[i][k] = corner[3 + k][i][lane];
    }
    fan.degenerate = (degenerate >> lane) & 1;
    faces[lane].firstFan = firstFans[lane];
    faces[lane].fanCount = 1;
    records[lane]->face = faces[lane];
  }
}

}  // namespace zrender
