#pragma once

// The scalar surface kernel, one sample at a time: the reference that the vector kernel
// (SurfaceKernelAvx2.cpp) matches bit for bit. Private to the shading stage. Inline, so that
// where it is compiled for AVX2 (the vector kernel's polygons) its fused multiply-adds are one
// instruction, and elsewhere the library's exact fmaf: the same bits either way.

#include <immintrin.h>

#include <cmath>
#include <cstdint>

#include "zrender/shading/SurfaceKernel.hpp"

namespace zrender::surface {

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
// A color channel, 0..255 plus 0.5 for rounding, is at most this before truncation to a byte;
// min(NaN, kTopChannel) is kTopChannel, as with _mm256_min_ps.
constexpr float kTopChannel = 255.5f;

// Plane k's value along a row (its b and c terms), then at a sample of that row.
[[gnu::always_inline]] inline float rowValue(const SurfaceFan& fan, int k, float sy) {
  return std::fma(fan.b[k], sy, fan.c[k]);
}
[[gnu::always_inline]] inline float planeAt(const SurfaceFan& fan, int k, float sx, float sy) {
  return std::fma(fan.a[k], sx, rowValue(fan, k, sy));
}

// Truncation toward zero as cvttps2dq does it (NaN and overflow give INT32_MIN).
[[gnu::always_inline]] inline uint32_t truncateToInt(float t) {
  return uint32_t(_mm_cvttss_si32(_mm_set_ss(t)));
}

// (a * w0 + b * u) + c * v as the vector kernel computes it.
[[gnu::always_inline]] inline float blend3(float a, float b, float c, float w0, float u, float v) {
  return std::fma(c, v, std::fma(b, u, a * w0));
}

// The normal (up to a positive factor) and texture coordinates at a sample of a fan.
[[gnu::always_inline]] inline void attributesAt(const SurfaceFan& fan, float sx, float sy,
                                                float m[3], float uv[2]) {
  const float d = planeAt(fan, kDen, sx, sy);
  const float a = planeAt(fan, kPu, sx, sy), b = planeAt(fan, kPv, sx, sy);
  const float w = (d - a) - b;
  if (d > 0.0f && a >= 0.0f && b >= 0.0f && w >= 0.0f) {
    for (int i = 0; i < 3; ++i) m[i] = planeAt(fan, kNormalX + i, sx, sy);
    const float inv = 1.0f / d;
    for (int k = 0; k < 2; ++k) uv[k] = planeAt(fan, kTextureU + k, sx, sy) * inv;
    return;
  }
  // Outside: the weights of the nearest point of the triangle.
  float u = 0.0f, v = 0.0f;
  if (!fan.degenerate) {
    const float inv = 1.0f / d;
    u = minOf(maxOf(a * inv, 0.0f), kHugeWeight);
    v = minOf(maxOf(b * inv, 0.0f), kHugeWeight);
    const float s = u + v;
    if (s > 1.0f) {
      const float invS = 1.0f / s;
      u = u * invS;
      v = v * invS;
    }
  }
  const float w0 = (1.0f - u) - v;
  for (int i = 0; i < 3; ++i)
    m[i] = blend3(fan.cornerNormal[0][i], fan.cornerNormal[1][i], fan.cornerNormal[2][i], w0, u, v);
  for (int k = 0; k < 2; ++k)
    uv[k] = blend3(fan.cornerUv[0][k], fan.cornerUv[1][k], fan.cornerUv[2][k], w0, u, v);
}

// The texture, bilinear, wrapping, at (u, v) (v = 0 is the bottom row); RGB in 0..255. Thanks
// to the frame of copied texels (SurfaceTexture) the four texels are (x0, y0) to (x0 + 1,
// y0 + 1) with x0 in [-1, width - 1] and y0 in [-1, height - 1], no wrapping needed.
[[gnu::always_inline]] inline void sampleTexture(const SurfaceTexture& t, float u, float v,
                                                 float rgb[3]) {
  // In [0, 1]; NaN (from an infinite u) to 0.
  const float uu = maxOf(u - std::floor(u), 0.0f), vv = maxOf(v - std::floor(v), 0.0f);
  const float tx = std::fma(uu, float(t.width), -0.5f);
  const float ty = std::fma(vv, -float(t.height), float(t.height) - 0.5f);
  const float fx0 = std::floor(tx), fy0 = std::floor(ty);
  const float fx = tx - fx0, fy = ty - fy0;
  const int stride = t.width + 2;
  const uint32_t* row0 =
      t.texels + (int(truncateToInt(fy0)) * stride + int(truncateToInt(fx0)) + (stride + 1));
  const uint32_t* row1 = row0 + stride;
  for (int i = 0; i < 3; ++i) {
    const int shift = 16 - 8 * i;  // R, G, B
    const float a = float((row0[0] >> shift) & 0xFF), b = float((row0[1] >> shift) & 0xFF);
    const float c = float((row1[0] >> shift) & 0xFF), d = float((row1[1] >> shift) & 0xFF);
    const float top = std::fma(b - a, fx, a), bottom = std::fma(d - c, fx, c);
    rgb[i] = std::fma(bottom - top, fy, top);
  }
}

// The fan triangle of a polygon that holds the sample: the first, else the one it misses
// least.
[[gnu::always_inline]] inline const SurfaceFan* fanAt(const FaceSurface& face,
                                                      const SurfaceFan* fans, float sx, float sy) {
  const SurfaceFan* fan = fans;
  float bestMiss = INFINITY;
  for (uint32_t j = 0; j < face.fanCount; ++j) {
    if (fans[j].degenerate) continue;
    const float inv = 1.0f / planeAt(fans[j], kDen, sx, sy);
    const float u = planeAt(fans[j], kPu, sx, sy) * inv, v = planeAt(fans[j], kPv, sx, sy) * inv;
    const float miss = maxOf(maxOf(maxOf(-u, -v), (u + v) - 1.0f), 0.0f);
    if (miss < bestMiss) {
      bestMiss = miss, fan = fans + j;
      if (miss == 0.0f) break;
    }
  }
  return fan;
}

// The normal (up to a positive factor, +Z where it vanishes) and texture coordinates at sample
// (x, y) of the face; returns the normal's squared length.
[[gnu::always_inline]] inline float surfaceAt(const FaceSurface& face, const SurfaceFan* fans,
                                              int x, int y, float m[3], float uv[2]) {
  const float sx = float(x - face.originX), sy = float(y - face.originY);
  const SurfaceFan* fan = face.fanCount > 1 ? fanAt(face, fans, sx, sy) : fans;
  attributesAt(*fan, sx, sy, m, uv);
  float length2 = std::fma(m[0], m[0], std::fma(m[1], m[1], m[2] * m[2]));
  if (!(length2 > 0.0f)) m[0] = 0.0f, m[1] = 0.0f, m[2] = 1.0f, length2 = 1.0f;  // +Z
  return length2;
}

// The packed color (0x00RRGGBB) of sample (x, y) of the face.
[[gnu::always_inline]] inline uint32_t shadeSample(const SurfaceFrame& f, const FaceSurface& face,
                                                   const SurfaceFan* fans, int x, int y) {
  float m[3], uv[2];
  const float length2 = surfaceAt(face, fans, x, y, m, uv);
  float t[3];
  if (f.mode == ShadingMode::Normal) {
    // (n + 1) / 2 of the unit normal n, times 255, plus 0.5.
    const float scale = 127.5f / std::sqrt(length2);
    for (int i = 0; i < 3; ++i) t[i] = std::fma(m[i], scale, 128.0f);
  } else {
    // The light is at the eye: the direction to it is minus the sample's ray d = (dx, dy, -1),
    // so the Lambert term is (m . -d) / (|m| |d|).
    const float dx = std::fma(float(x), f.rayScaleX, f.rayOriginX);
    const float dy = std::fma(float(y), -f.rayScaleY, f.rayOriginY);
    const float ray2 = std::fma(dx, dx, std::fma(dy, dy, 1.0f));
    const float dot = std::fma(-m[0], dx, std::fma(-m[1], dy, m[2]));
    const float diffuse = maxOf(dot, 0.0f) / std::sqrt(length2 * ray2);
    float shine = 0.5f;  // to round
    if (diffuse >= kNoSpecular) {
      float specular = diffuse;
      for (int k = 0; k < 6; ++k) specular = specular * specular;  // ^64
      shine = std::fma(76.5f, specular, 0.5f);                     // white specular 0.3, times 255
    }
    // Ambient 0.1, diffuse 0.9.
    const float light = std::fma(0.9f, diffuse, 0.1f);
    float base[3] = {face.base[0], face.base[1], face.base[2]};
    if (face.textured()) sampleTexture(f.textures[face.texture], uv[0], uv[1], base);
    for (int i = 0; i < 3; ++i) t[i] = std::fma(base[i], light, shine);
  }
  return truncateToInt(minOf(t[0], kTopChannel)) << 16 |
         truncateToInt(minOf(t[1], kTopChannel)) << 8 | truncateToInt(minOf(t[2], kTopChannel));
}

}  // namespace zrender::surface
