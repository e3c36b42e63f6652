#pragma once

#include <immintrin.h>

#include <cstdint>

#include "zrender/base/CpuFeatures.hpp"
#include "zrender/raster/RasterRules.hpp"

namespace zrender {

// Moving a row of samples along, for the shader: where a run of one face's samples ends, and
// packed colors to image bytes. Pure data movement: the AVX2 versions give the same results
// as the scalar ones.

// The end of the run of samples from x that hold the face id of keys[x]: the first index
// after x whose key has another id, or `width`.
int runEndScalar(const DepthKey* keys, int x, int width);
// Eight keys at a time. Call only when cpuHasAvx2(). Inline: the shading's row loops call it
// for every run.
ZRENDER_AVX2 inline int runEndAvx2(const DepthKey* keys, int x, int width) {
  const uint32_t id = keyFaceId(keys[x]);
  const __m256i wanted = _mm256_set1_epi32(int(id));
  int end = x + 1;
  for (; end + 8 <= width; end += 8) {
    // The low halves (ids) of eight keys, in order.
    const __m256 a = _mm256_loadu_ps(reinterpret_cast<const float*>(keys + end));
    const __m256 b = _mm256_loadu_ps(reinterpret_cast<const float*>(keys + end + 4));
    const __m256i ids = _mm256_castpd_si256(
        _mm256_permute4x64_pd(_mm256_castps_pd(_mm256_shuffle_ps(a, b, 0x88)), 0xD8));
    const unsigned same =
        unsigned(_mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(ids, wanted))));
    if (same != 0xFFu) return end + __builtin_ctz(~same);
  }
  while (end < width && keyFaceId(keys[end]) == id) ++end;
  return end;
}

// Eight packed colors (0x00RRGGBB) as B, G, R bytes: each 128-bit half's four pixels in its low
// 12 bytes, its top 4 bytes zero.
ZRENDER_AVX2 inline __m256i squeezeBgr(__m256i colors) {
  const __m256i squeeze = _mm256_setr_epi8(0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, -1, -1, -1, -1,
                                           0, 1, 2, 4, 5, 6, 8, 9, 10, 12, 13, 14, -1, -1, -1, -1);
  return _mm256_shuffle_epi8(colors, squeeze);
}

// Writes `count` packed colors (0x00RRGGBB) as BGR bytes into out[0, 3 count).
void packBgrScalar(const uint32_t* colors, int count, unsigned char* out);
// Eight pixels at a time. Call only when cpuHasAvx2().
void packBgrAvx2(const uint32_t* colors, int count, unsigned char* out);

using RunEndFunction = int (*)(const DepthKey*, int, int);
using PackBgrFunction = void (*)(const uint32_t*, int, unsigned char*);
// The AVX2 versions where the CPU has AVX2, else the scalar ones.
RunEndFunction runEnd();
PackBgrFunction packBgr();

}  // namespace zrender
