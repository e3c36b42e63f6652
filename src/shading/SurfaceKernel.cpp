#include "zrender/shading/SurfaceKernel.hpp"

#include <immintrin.h>

#include <algorithm>
#include <cmath>

#include "zrender/base/CpuFeatures.hpp"
#include "zrender/shading/PixelRows.hpp"
#include "zrender/shading/SurfaceSetup.hpp"

namespace zrender {

namespace {

// The scalar twins of _mm256_max_ps and _mm256_min_ps, NaN included: the second operand
// unless the first is greater (smaller).
inline float maxOf(float a, float b) {
  return a > b ? a : b;
}
inline float minOf(float a, float b) {
  return a < b ? a : b;
}

// Beyond any weight a sample can have; infinite weights (a sample on the horizon of its face's
// plane) are brought down to it so that no NaN follows.
constexpr float kHugeWeight = 1e30f;
// Below this Lambert term the specular term, its 64th power, is under 2^-64: none of a color's
// 1/255. Its squares would turn into denormal floats, which cost the CPU many times a normal
// multiply, so it is 0 there.
constexpr float kNoSpecular = 0.5f;

// A plane's value along a row (its c and b terms), then at a sample of that row.
inline float rowValue(const SamplePlane& p, float sy) {
  return p.c + p.b * sy;
}
inline float atSample(const SamplePlane& p, float row, float sx) {
  return row + p.a * sx;
}
inline float planeAt(const SamplePlane& p, float sx, float sy) {
  return atSample(p, rowValue(p, sy), sx);
}

// The normal (up to a positive factor) and texture coordinates at a sample of a fan.
void attributesAt(const SurfaceFan& fan, float sx, float sy, float m[3], float uv[2]) {
  const float den = planeAt(fan.den, sx, sy);
  const float pu = planeAt(fan.pu, sx, sy), pv = planeAt(fan.pv, sx, sy);
  // den's sign taken out: inside the triangle the three weights are then all >= 0.
  const bool negative = std::signbit(den);
  const float d = negative ? -den : den, a = negative ? -pu : pu, b = negative ? -pv : pv;
  const float w = (d - a) - b;
  if (d > 0.0f && minOf(minOf(a, b), w) >= 0.0f) {
    for (int i = 0; i < 3; ++i) {
      const float value = planeAt(fan.normal[i], sx, sy);
      m[i] = negative ? -value : value;
    }
    const float inv = 1.0f / den;
    for (int k = 0; k < 2; ++k) uv[k] = planeAt(fan.uv[k], sx, sy) * inv;
    return;
  }
  // Outside: the weights of the nearest point of the triangle.
  float u = 0.0f, v = 0.0f;
  if (!fan.degenerate) {
    const float inv = 1.0f / den;
    u = minOf(maxOf(pu * inv, 0.0f), kHugeWeight);
    v = minOf(maxOf(pv * inv, 0.0f), kHugeWeight);
    const float s = u + v;
    if (s > 1.0f) {
      const float invS = 1.0f / s;
      u = u * invS;
      v = v * invS;
    }
  }
  const float w0 = (1.0f - u) - v;
  for (int i = 0; i < 3; ++i)
    m[i] = (fan.cornerNormal[0][i] * w0 + fan.cornerNormal[1][i] * u) + fan.cornerNormal[2][i] * v;
  for (int k = 0; k < 2; ++k)
    uv[k] = (fan.cornerUv[0][k] * w0 + fan.cornerUv[1][k] * u) + fan.cornerUv[2][k] * v;
}

// The texture, bilinear, wrapping, at (u, v) (v = 0 is the bottom row); RGB in 0..255. The
// texels are stored with a copy of the first column after the last and of the first row after
// the last (SurfaceFrame), so the four texels are (x0, y0) to (x0 + 1, y0 + 1) with only x0
// and y0 wrapped, and the two of a row are adjacent.
void sampleTexture(const SurfaceFrame& f, float u, float v, float rgb[3]) {
  float uu = u - std::floor(u), vv = v - std::floor(v);
  uu = minOf(maxOf(uu, 0.0f), 1.0f);  // NaN (from an infinite u) to 0
  vv = minOf(maxOf(vv, 0.0f), 1.0f);
  const float tx = uu * float(f.textureWidth) - 0.5f;
  const float ty = (1.0f - vv) * float(f.textureHeight) - 0.5f;
  const float fx0 = std::floor(tx), fy0 = std::floor(ty);
  const float fx = tx - fx0, fy = ty - fy0;
  // The coordinates lie in [-0.5, size - 0.5]: x0 and y0 in [-1, size - 1].
  int x0 = int(fx0), y0 = int(fy0);
  x0 = x0 < 0 ? x0 + f.textureWidth : x0;
  y0 = y0 < 0 ? y0 + f.textureHeight : y0;
  const int stride = f.textureWidth + 1;
  const uint32_t* row0 = f.texels + y0 * stride + x0;
  const uint32_t* row1 = row0 + stride;
  for (int i = 0; i < 3; ++i) {
    const int shift = 16 - 8 * i;  // R, G, B
    const float top =
        float((row0[0] >> shift) & 0xFF) * (1.0f - fx) + float((row0[1] >> shift) & 0xFF) * fx;
    const float bottom =
        float((row1[0] >> shift) & 0xFF) * (1.0f - fx) + float((row1[1] >> shift) & 0xFF) * fx;
    rgb[i] = top * (1.0f - fy) + bottom * fy;
  }
}

// A color channel in 0..255 plus 0.5, to its byte (truncated, so rounded).
inline uint32_t toByte(float t) {
  return uint32_t(minOf(maxOf(t, 0.5f), 255.5f));
}

uint32_t shadeSample(const SurfaceFrame& f, const FaceSurface& face, const SurfaceFan* fans, int x,
                     int y) {
  const float sx = float(x - face.originX), sy = float(y - face.originY);
  // The fan triangle that holds the sample: the first, else the one it misses least.
  const SurfaceFan* fan = fans;
  if (face.fanCount > 1) {
    float bestMiss = INFINITY;
    for (uint32_t j = 0; j < face.fanCount; ++j) {
      if (fans[j].degenerate) continue;
      const float inv = 1.0f / planeAt(fans[j].den, sx, sy);
      const float u = planeAt(fans[j].pu, sx, sy) * inv, v = planeAt(fans[j].pv, sx, sy) * inv;
      const float miss = maxOf(maxOf(maxOf(-u, -v), (u + v) - 1.0f), 0.0f);
      if (miss < bestMiss) {
        bestMiss = miss, fan = fans + j;
        if (miss == 0.0f) break;
      }
    }
  }
  float m[3], uv[2];
  attributesAt(*fan, sx, sy, m, uv);
  float length2 = (m[0] * m[0] + m[1] * m[1]) + m[2] * m[2];
  if (!(length2 > 0.0f)) m[0] = 0.0f, m[1] = 0.0f, m[2] = 1.0f, length2 = 1.0f;  // +Z
  float t[3];
  if (f.mode == ShadingMode::Normal) {
    // (n + 1) / 2 of the unit normal n, times 255, plus 0.5.
    const float scale = 127.5f / std::sqrt(length2);
    for (int i = 0; i < 3; ++i) t[i] = m[i] * scale + 128.0f;
  } else {
    // 0 - c rather than -c, here and below: the vector code's operation, zeros' signs included.
    if (face.flip)
      for (float& c : m) c = 0.0f - c;
    // The light is at the eye: the direction to it is minus the sample's ray d = (dx, dy, -1),
    // so the Lambert term is (m . -d) / (|m| |d|).
    const float dx = f.rayOriginX + (float(x) + 0.5f) * f.rayScaleX;
    const float dy = f.rayOriginY - (float(y) + 0.5f) * f.rayScaleY;
    const float ray2 = dx * dx + (dy * dy + 1.0f);
    const float dot = m[2] - (m[0] * dx + m[1] * dy);
    const float diffuse = maxOf(dot, 0.0f) / std::sqrt(length2 * ray2);
    float specular = maxOf(diffuse, kNoSpecular);
    for (int k = 0; k < 6; ++k) specular = specular * specular;  // ^64
    specular = diffuse >= kNoSpecular ? specular : 0.0f;
    // Ambient 0.1, diffuse 0.9, white specular 0.3 (times 255), and 0.5 to round.
    const float light = 0.1f + 0.9f * diffuse, shine = 76.5f * specular + 0.5f;
    float base[3] = {face.base[0], face.base[1], face.base[2]};
    if (face.textured) sampleTexture(f, uv[0], uv[1], base);
    for (int i = 0; i < 3; ++i) t[i] = base[i] * light + shine;
  }
  return toByte(t[0]) << 16 | toByte(t[1]) << 8 | toByte(t[2]);
}

}  // namespace

void shadeSurfaceRunScalar(const SurfaceFrame& frame, const FaceSurface& face,
                           const SurfaceFan* fans, int x, int y, int count, uint32_t* out) {
  for (int i = 0; i < count; ++i) out[i] = shadeSample(frame, face, fans, x + i, y);
}

namespace {

// The vector versions: SurfaceLanes.inl for eight lanes (AVX2) and sixteen (AVX-512).

namespace lanes8 {

#define ZRENDER_LANES ZRENDER_AVX2
#define SHADE_SHORT_OR_LONG_RUN shadeTriangleRun
using F = __m256;
using I = __m256i;
using M = __m256;
constexpr int kLanes = 8;

ZRENDER_LANES inline F splat(float x) {
  return _mm256_set1_ps(x);
}
ZRENDER_LANES inline F iota() {
  return _mm256_setr_ps(0, 1, 2, 3, 4, 5, 6, 7);
}
ZRENDER_LANES inline F add(F a, F b) {
  return _mm256_add_ps(a, b);
}
ZRENDER_LANES inline F sub(F a, F b) {
  return _mm256_sub_ps(a, b);
}
ZRENDER_LANES inline F mul(F a, F b) {
  return _mm256_mul_ps(a, b);
}
ZRENDER_LANES inline F div(F a, F b) {
  return _mm256_div_ps(a, b);
}
ZRENDER_LANES inline F sqrt(F a) {
  return _mm256_sqrt_ps(a);
}
ZRENDER_LANES inline F min(F a, F b) {
  return _mm256_min_ps(a, b);
}
ZRENDER_LANES inline F max(F a, F b) {
  return _mm256_max_ps(a, b);
}
ZRENDER_LANES inline F floor(F a) {
  return _mm256_floor_ps(a);
}
ZRENDER_LANES inline F signOf(F a) {
  return _mm256_and_ps(a, _mm256_set1_ps(-0.0f));
}
ZRENDER_LANES inline F flipBy(F a, F sign) {
  return _mm256_xor_ps(a, sign);
}
ZRENDER_LANES inline M gt(F a, F b) {
  return _mm256_cmp_ps(a, b, _CMP_GT_OQ);
}
ZRENDER_LANES inline M ge(F a, F b) {
  return _mm256_cmp_ps(a, b, _CMP_GE_OQ);
}
ZRENDER_LANES inline M mand(M a, M b) {
  return _mm256_and_ps(a, b);
}
ZRENDER_LANES inline M mor(M a, M b) {
  return _mm256_or_ps(a, b);
}
ZRENDER_LANES inline bool all(M m) {
  return _mm256_movemask_ps(m) == 0xFF;
}
ZRENDER_LANES inline F select(M m, F ifTrue, F ifFalse) {
  return _mm256_blendv_ps(ifFalse, ifTrue, m);
}
ZRENDER_LANES inline I cvtt(F a) {
  return _mm256_cvttps_epi32(a);
}
ZRENDER_LANES inline I isplat(int x) {
  return _mm256_set1_epi32(x);
}
ZRENDER_LANES inline I iadd(I a, I b) {
  return _mm256_add_epi32(a, b);
}
ZRENDER_LANES inline I imul(I a, I b) {
  return _mm256_mullo_epi32(a, b);
}
ZRENDER_LANES inline I ior(I a, I b) {
  return _mm256_or_si256(a, b);
}
ZRENDER_LANES inline I ishl(I a, int n) {
  return _mm256_sll_epi32(a, _mm_cvtsi32_si128(n));
}
// x + size where x < 0.
ZRENDER_LANES inline I wrapNegative(I x, int size) {
  return _mm256_add_epi32(
      x, _mm256_and_si256(_mm256_cmpgt_epi32(_mm256_setzero_si256(), x), _mm256_set1_epi32(size)));
}
// One 8-bit channel of texels, as floats 0..255.
ZRENDER_LANES inline F channel(I texels, int shift) {
  return _mm256_cvtepi32_ps(_mm256_and_si256(_mm256_srl_epi32(texels, _mm_cvtsi32_si128(shift)),
                                             _mm256_set1_epi32(0xFF)));
}
// The texels at `index` and index + 1: one 64-bit gather element each.
ZRENDER_LANES inline void gatherPairs(const uint32_t* texels, I index, I& left, I& right) {
  const long long* base = reinterpret_cast<const long long*>(texels);
  const __m256 lo =
      _mm256_castsi256_ps(_mm256_i32gather_epi64(base, _mm256_castsi256_si128(index), 4));
  const __m256 hi =
      _mm256_castsi256_ps(_mm256_i32gather_epi64(base, _mm256_extracti128_si256(index, 1), 4));
  // Even 32-bit halves (the left texels) and odd ones, lanes in order.
  left = _mm256_castpd_si256(
      _mm256_permute4x64_pd(_mm256_castps_pd(_mm256_shuffle_ps(lo, hi, 0x88)), 0xD8));
  right = _mm256_castpd_si256(
      _mm256_permute4x64_pd(_mm256_castps_pd(_mm256_shuffle_ps(lo, hi, 0xDD)), 0xD8));
}
ZRENDER_LANES inline void store(uint32_t* out, I a) {
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(out), a);
}

#include "SurfaceLanes.inl"
#undef ZRENDER_LANES
#undef SHADE_SHORT_OR_LONG_RUN

}  // namespace lanes8

// GCC 12's avx512fintrin.h passes an undefined vector (_mm512_undefined_ps) as the unused
// pass-through of _mm512_min_ps and _mm512_max_ps, which -Wmaybe-uninitialized reports.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

namespace lanes16 {

#define ZRENDER_LANES ZRENDER_AVX512
// Runs of up to 8 samples (small faces) take the eight-lane loop: sixteen lanes would compute
// twice the samples kept. The lanes give the same bits whatever their number.
#define SHADE_SHORT_OR_LONG_RUN(frame, face, fan, x, y, count, out)            \
  ((count) <= 8 ? lanes8::shadeTriangleRun(frame, face, fan, x, y, count, out) \
                : shadeTriangleRun(frame, face, fan, x, y, count, out))
using F = __m512;
using I = __m512i;
using M = __mmask16;
constexpr int kLanes = 16;

ZRENDER_LANES inline F splat(float x) {
  return _mm512_set1_ps(x);
}
ZRENDER_LANES inline F iota() {
  return _mm512_setr_ps(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
}
ZRENDER_LANES inline F add(F a, F b) {
  return _mm512_add_ps(a, b);
}
ZRENDER_LANES inline F sub(F a, F b) {
  return _mm512_sub_ps(a, b);
}
ZRENDER_LANES inline F mul(F a, F b) {
  return _mm512_mul_ps(a, b);
}
ZRENDER_LANES inline F div(F a, F b) {
  return _mm512_div_ps(a, b);
}
ZRENDER_LANES inline F sqrt(F a) {
  return _mm512_sqrt_ps(a);
}
ZRENDER_LANES inline F min(F a, F b) {
  return _mm512_min_ps(a, b);
}
ZRENDER_LANES inline F max(F a, F b) {
  return _mm512_max_ps(a, b);
}
ZRENDER_LANES inline F floor(F a) {
  return _mm512_floor_ps(a);
}
ZRENDER_LANES inline F signOf(F a) {
  return _mm512_castsi512_ps(
      _mm512_and_si512(_mm512_castps_si512(a), _mm512_set1_epi32(int(0x80000000u))));
}
ZRENDER_LANES inline F flipBy(F a, F sign) {
  return _mm512_castsi512_ps(_mm512_xor_si512(_mm512_castps_si512(a), _mm512_castps_si512(sign)));
}
ZRENDER_LANES inline M gt(F a, F b) {
  return _mm512_cmp_ps_mask(a, b, _CMP_GT_OQ);
}
ZRENDER_LANES inline M ge(F a, F b) {
  return _mm512_cmp_ps_mask(a, b, _CMP_GE_OQ);
}
ZRENDER_LANES inline M mand(M a, M b) {
  return M(a & b);
}
ZRENDER_LANES inline M mor(M a, M b) {
  return M(a | b);
}
ZRENDER_LANES inline bool all(M m) {
  return m == 0xFFFF;
}
ZRENDER_LANES inline F select(M m, F ifTrue, F ifFalse) {
  return _mm512_mask_blend_ps(m, ifFalse, ifTrue);
}
ZRENDER_LANES inline I cvtt(F a) {
  return _mm512_cvttps_epi32(a);
}
ZRENDER_LANES inline I isplat(int x) {
  return _mm512_set1_epi32(x);
}
ZRENDER_LANES inline I iadd(I a, I b) {
  return _mm512_add_epi32(a, b);
}
ZRENDER_LANES inline I imul(I a, I b) {
  return _mm512_mullo_epi32(a, b);
}
ZRENDER_LANES inline I ior(I a, I b) {
  return _mm512_or_si512(a, b);
}
ZRENDER_LANES inline I ishl(I a, int n) {
  return _mm512_sll_epi32(a, _mm_cvtsi32_si128(n));
}
ZRENDER_LANES inline I wrapNegative(I x, int size) {
  return _mm512_mask_add_epi32(x, _mm512_cmplt_epi32_mask(x, _mm512_setzero_si512()), x,
                               _mm512_set1_epi32(size));
}
ZRENDER_LANES inline F channel(I texels, int shift) {
  return _mm512_cvtepi32_ps(_mm512_and_si512(_mm512_srl_epi32(texels, _mm_cvtsi32_si128(shift)),
                                             _mm512_set1_epi32(0xFF)));
}
ZRENDER_LANES inline void gatherPairs(const uint32_t* texels, I index, I& left, I& right) {
  const long long* base = reinterpret_cast<const long long*>(texels);
  const __m512i lo = _mm512_i32gather_epi64(_mm512_castsi512_si256(index), base, 4);
  const __m512i hi = _mm512_i32gather_epi64(_mm512_extracti64x4_epi64(index, 1), base, 4);
  // Even 32-bit halves of lo then hi (the left texels), and the odd ones.
  const __m512i even = _mm512_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14, 16, 18, 20, 22, 24, 26, 28, 30);
  left = _mm512_permutex2var_epi32(lo, even, hi);
  right = _mm512_permutex2var_epi32(lo, _mm512_add_epi32(even, _mm512_set1_epi32(1)), hi);
}
ZRENDER_LANES inline void store(uint32_t* out, I a) {
  _mm512_storeu_si512(out, a);
}

#include "SurfaceLanes.inl"
#undef ZRENDER_LANES
#undef SHADE_SHORT_OR_LONG_RUN

}  // namespace lanes16

#pragma GCC diagnostic pop

}  // namespace

namespace {

// Runs through a buffer with room for the last block past them.
template <int kLanes, typename Run>
void runThroughBuffer(int count, uint32_t* out, Run run) {
  uint32_t buffer[256 + kLanes];
  for (int i = 0; i < count; i += 256) {
    const int n = std::min(256, count - i);
    run(i, n, buffer);
    std::copy(buffer, buffer + n, out + i);
  }
}

}  // namespace

ZRENDER_AVX2 void shadeSurfaceRunAvx2(const SurfaceFrame& frame, const FaceSurface& face,
                                      const SurfaceFan* fans, int x, int y, int count,
                                      uint32_t* out) {
  if (face.fanCount != 1) {  // polygons: the scalar path, the same bits
    shadeSurfaceRunScalar(frame, face, fans, x, y, count, out);
    return;
  }
  runThroughBuffer<8>(count, out, [&](int i, int n, uint32_t* buffer) ZRENDER_AVX2 {
    lanes8::shadeTriangleRun(frame, face, *fans, x + i, y, n, buffer);
  });
}

ZRENDER_AVX512 void shadeSurfaceRunAvx512(const SurfaceFrame& frame, const FaceSurface& face,
                                          const SurfaceFan* fans, int x, int y, int count,
                                          uint32_t* out) {
  if (face.fanCount != 1) {
    shadeSurfaceRunScalar(frame, face, fans, x, y, count, out);
    return;
  }
  runThroughBuffer<16>(count, out, [&](int i, int n, uint32_t* buffer) ZRENDER_AVX512 {
    lanes16::shadeTriangleRun(frame, face, *fans, x + i, y, n, buffer);
  });
}

void shadeSurfaceRowScalar(SurfaceSetup& setup, const DepthKey* keys, int width, int y,
                           uint32_t background, uint32_t* out) {
  for (int x = 0; x < width;) {
    const int end = runEndScalar(keys, x, width);
    const uint32_t id = keyFaceId(keys[x]);
    if (id == kBackgroundId) {
      for (int i = x; i < end; ++i) out[i] = background;
    } else {
      const FaceSurface& face = setup.surface(id);
      shadeSurfaceRunScalar(setup.frame(), face, setup.fans(face), x, y, end - x, out + x);
    }
    x = end;
  }
}

void shadeSurfaceRowAvx2(SurfaceSetup& setup, const DepthKey* keys, int width, int y,
                         uint32_t background, uint32_t* out) {
  lanes8::shadeRow(setup, keys, width, y, background, out);
}

void shadeSurfaceRowAvx512(SurfaceSetup& setup, const DepthKey* keys, int width, int y,
                           uint32_t background, uint32_t* out) {
  lanes16::shadeRow(setup, keys, width, y, background, out);
}

SurfaceRowFunction surfaceRow() {
  if (cpuHasAvx512()) return shadeSurfaceRowAvx512;
  return cpuHasAvx2() ? shadeSurfaceRowAvx2 : shadeSurfaceRowScalar;
}

}  // namespace zrender
