#include "zrender/VertexProjection.hpp"

#include <immintrin.h>

#include <cmath>

namespace zrender {

void projectVertex(const Mat4& mvp, const Vec3& position, const VertexViewport& viewport,
                   uint32_t frame, VertexState& state, Vec3& window) {
  const Vec4 c = mvp * Vec4(position[0], position[1], position[2], 1.0);
  state.frame = frame;
  if (!(std::isfinite(c[0]) && std::isfinite(c[1]) && std::isfinite(c[2]) && std::isfinite(c[3]))) {
    state.code = kNotFinite;
    return;
  }
  state.code = (c[0] < -c[3]) | (c[0] > c[3]) << 1 | (c[1] < -c[3]) << 2 | (c[1] > c[3]) << 3 |
               (c[2] < -c[3]) << 4 | (c[2] > c[3]) << 5;
  if (state.code & (kNear | kFar)) return;
  window = clipToWindow(c, viewport.width, viewport.height);
  const double guard = kGuardBand / viewport.scale;
  if (std::abs(window[0]) > guard || std::abs(window[1]) > guard) {
    state.code |= kGuard;
    return;
  }
  // Snap to 1/256 pixel, then scale to samples.
  state.snapped = {snapToSubpixel(window[0]) * viewport.scale,
                   snapToSubpixel(window[1]) * viewport.scale};
}

// Lane k holds vertex k. Bit-identical to projectVertex because each step is the same IEEE
// operation in the same order: cv::Matx's product starts its sums at 0 (0 + m x, then + m y,
// + m z, + m w with w = 1), no FMA (not enabled for this function, contraction off),
// clipToWindow's 1 / w then products, and the snap's rounding to nearest (even) under the same
// rounding mode as lrint; the guard band keeps the snapped values within int32.
__attribute__((target("avx2"))) void projectVertices4Avx2(const Mat4& mvp,
                                                          const Vec3* const positions[4],
                                                          const VertexViewport& viewport,
                                                          uint32_t frame, VertexState* states,
                                                          Vec3* windows) {
  const __m256d x = _mm256_setr_pd(positions[0]->val[0], positions[1]->val[0], positions[2]->val[0],
                                   positions[3]->val[0]);
  const __m256d y = _mm256_setr_pd(positions[0]->val[1], positions[1]->val[1], positions[2]->val[1],
                                   positions[3]->val[1]);
  const __m256d z = _mm256_setr_pd(positions[0]->val[2], positions[1]->val[2], positions[2]->val[2],
                                   positions[3]->val[2]);
  const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
  __m256d c[4];
  for (int i = 0; i < 4; ++i) {
    __m256d s = _mm256_add_pd(zero, _mm256_mul_pd(_mm256_set1_pd(mvp(i, 0)), x));
    s = _mm256_add_pd(s, _mm256_mul_pd(_mm256_set1_pd(mvp(i, 1)), y));
    s = _mm256_add_pd(s, _mm256_mul_pd(_mm256_set1_pd(mvp(i, 2)), z));
    c[i] = _mm256_add_pd(s, _mm256_mul_pd(_mm256_set1_pd(mvp(i, 3)), one));
  }
  const __m256d signBit = _mm256_set1_pd(-0.0), infinity = _mm256_set1_pd(HUGE_VAL);
  __m256d finite = _mm256_cmp_pd(_mm256_andnot_pd(signBit, c[0]), infinity, _CMP_LT_OQ);
  for (int i = 1; i < 4; ++i)
    finite =
        _mm256_and_pd(finite, _mm256_cmp_pd(_mm256_andnot_pd(signBit, c[i]), infinity, _CMP_LT_OQ));
  const __m256d minusW = _mm256_xor_pd(c[3], signBit);
  // Per outcode bit, a 4-bit mask of the lanes that have it.
  const int below[3] = {_mm256_movemask_pd(_mm256_cmp_pd(c[0], minusW, _CMP_LT_OQ)),
                        _mm256_movemask_pd(_mm256_cmp_pd(c[1], minusW, _CMP_LT_OQ)),
                        _mm256_movemask_pd(_mm256_cmp_pd(c[2], minusW, _CMP_LT_OQ))};
  const int above[3] = {_mm256_movemask_pd(_mm256_cmp_pd(c[0], c[3], _CMP_GT_OQ)),
                        _mm256_movemask_pd(_mm256_cmp_pd(c[1], c[3], _CMP_GT_OQ)),
                        _mm256_movemask_pd(_mm256_cmp_pd(c[2], c[3], _CMP_GT_OQ))};
  const int finiteLanes = _mm256_movemask_pd(finite);

  const __m256d half = _mm256_set1_pd(0.5);
  const __m256d invW = _mm256_div_pd(one, c[3]);
  const __m256d wx =
      _mm256_mul_pd(_mm256_mul_pd(_mm256_add_pd(_mm256_mul_pd(c[0], invW), one), half),
                    _mm256_set1_pd(double(viewport.width)));
  const __m256d wy =
      _mm256_mul_pd(_mm256_mul_pd(_mm256_sub_pd(one, _mm256_mul_pd(c[1], invW)), half),
                    _mm256_set1_pd(double(viewport.height)));
  const __m256d wz = _mm256_mul_pd(_mm256_add_pd(_mm256_mul_pd(c[2], invW), one), half);
  const __m256d guard = _mm256_set1_pd(kGuardBand / viewport.scale);
  const int outside = _mm256_movemask_pd(
      _mm256_or_pd(_mm256_cmp_pd(_mm256_andnot_pd(signBit, wx), guard, _CMP_GT_OQ),
                   _mm256_cmp_pd(_mm256_andnot_pd(signBit, wy), guard, _CMP_GT_OQ)));
  const __m256d subpixel = _mm256_set1_pd(double(kSubpixel));
  const __m128i scale = _mm_set1_epi32(viewport.scale);
  alignas(16) int32_t sx[4], sy[4];
  _mm_store_si128(reinterpret_cast<__m128i*>(sx),
                  _mm_mullo_epi32(_mm256_cvtpd_epi32(_mm256_mul_pd(wx, subpixel)), scale));
  _mm_store_si128(reinterpret_cast<__m128i*>(sy),
                  _mm_mullo_epi32(_mm256_cvtpd_epi32(_mm256_mul_pd(wy, subpixel)), scale));
  alignas(32) double lx[4], ly[4], lz[4];
  _mm256_store_pd(lx, wx);
  _mm256_store_pd(ly, wy);
  _mm256_store_pd(lz, wz);

  for (int k = 0; k < 4; ++k) {
    VertexState& s = states[k];
    s.frame = frame;
    s.snapped = FixedPoint{sx[k], sy[k]};
    windows[k] = Vec3(lx[k], ly[k], lz[k]);
    if (!(finiteLanes >> k & 1)) {
      s.code = kNotFinite;
      continue;
    }
    uint32_t code = 0;
    for (int i = 0; i < 3; ++i)
      code |= uint32_t(below[i] >> k & 1) << (2 * i) | uint32_t(above[i] >> k & 1) << (2 * i + 1);
    if (!(code & (kNear | kFar)) && (outside >> k & 1)) code |= kGuard;
    s.code = code;
  }
}

}  // namespace zrender
