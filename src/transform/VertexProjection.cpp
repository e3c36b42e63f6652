#include "zrender/transform/VertexProjection.hpp"

#include <immintrin.h>

#include <cmath>
#include <cstddef>

#include "zrender/base/CpuFeatures.hpp"

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
ZRENDER_AVX2 void projectVertices4Avx2(const Mat4& mvp, const Vec3* const positions[4],
                                       const VertexViewport& viewport, uint32_t frame,
                                       VertexState* states, Vec3* windows) {
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
  // The outcode of each lane as a 64-bit integer: each comparison (all ones where true) keeps
  // its bit (VertexCode: kLeft << 2i below, kRight << 2i above, for x, y, z).
  __m256i code = _mm256_setzero_si256();
  for (int i = 0; i < 3; ++i) {
    const __m256i below = _mm256_castpd_si256(_mm256_cmp_pd(c[i], minusW, _CMP_LT_OQ));
    const __m256i above = _mm256_castpd_si256(_mm256_cmp_pd(c[i], c[3], _CMP_GT_OQ));
    code = _mm256_or_si256(code,
                           _mm256_and_si256(below, _mm256_set1_epi64x(int64_t(kLeft) << (2 * i))));
    code = _mm256_or_si256(code,
                           _mm256_and_si256(above, _mm256_set1_epi64x(int64_t(kRight) << (2 * i))));
  }

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
  // kGuard where inside near and far but beyond the guard band; kNotFinite alone where a clip
  // coordinate is NaN or infinite.
  const __m256i outside = _mm256_castpd_si256(
      _mm256_or_pd(_mm256_cmp_pd(_mm256_andnot_pd(signBit, wx), guard, _CMP_GT_OQ),
                   _mm256_cmp_pd(_mm256_andnot_pd(signBit, wy), guard, _CMP_GT_OQ)));
  const __m256i insideNearFar = _mm256_cmpeq_epi64(
      _mm256_and_si256(code, _mm256_set1_epi64x(kNear | kFar)), _mm256_setzero_si256());
  code = _mm256_or_si256(
      code, _mm256_and_si256(_mm256_and_si256(insideNearFar, outside), _mm256_set1_epi64x(kGuard)));
  code = _mm256_blendv_epi8(_mm256_set1_epi64x(kNotFinite), code, _mm256_castpd_si256(finite));
  // Low halves of the four 64-bit codes.
  const __m128i codes = _mm256_castsi256_si128(
      _mm256_permutevar8x32_epi32(code, _mm256_setr_epi32(0, 2, 4, 6, 0, 2, 4, 6)));

  const __m256d subpixel = _mm256_set1_pd(double(kSubpixel));
  const __m128i scale = _mm_set1_epi32(viewport.scale);
  const __m128i sx = _mm_mullo_epi32(_mm256_cvtpd_epi32(_mm256_mul_pd(wx, subpixel)), scale);
  const __m128i sy = _mm_mullo_epi32(_mm256_cvtpd_epi32(_mm256_mul_pd(wy, subpixel)), scale);
  // Lane k's state is (sx, sy, code, frame): a 4 x 4 transpose, one 16-byte store each.
  static_assert(sizeof(VertexState) == 16 && offsetof(VertexState, code) == 8 &&
                    offsetof(VertexState, frame) == 12,
                "VertexState is snapped x, y, code, frame");
  const __m128i xy01 = _mm_unpacklo_epi32(sx, sy), xy23 = _mm_unpackhi_epi32(sx, sy);
  const __m128i frames = _mm_set1_epi32(int32_t(frame));
  const __m128i cf01 = _mm_unpacklo_epi32(codes, frames), cf23 = _mm_unpackhi_epi32(codes, frames);
  _mm_storeu_si128(reinterpret_cast<__m128i*>(&states[0]), _mm_unpacklo_epi64(xy01, cf01));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(&states[1]), _mm_unpackhi_epi64(xy01, cf01));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(&states[2]), _mm_unpacklo_epi64(xy23, cf23));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(&states[3]), _mm_unpackhi_epi64(xy23, cf23));

  alignas(32) double lx[4], ly[4], lz[4];
  _mm256_store_pd(lx, wx);
  _mm256_store_pd(ly, wy);
  _mm256_store_pd(lz, wz);
  for (int k = 0; k < 4; ++k) windows[k] = Vec3(lx[k], ly[k], lz[k]);
}

}  // namespace zrender
