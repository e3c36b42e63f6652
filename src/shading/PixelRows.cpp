#include "zrender/shading/PixelRows.hpp"

#include <immintrin.h>

#include <cstring>

#include "zrender/base/CpuFeatures.hpp"

namespace zrender {

int runEndScalar(const DepthKey* keys, int x, int width) {
  const uint32_t id = keyFaceId(keys[x]);
  int end = x + 1;
  while (end < width && keyFaceId(keys[end]) == id) ++end;
  return end;
}

void packBgrScalar(const uint32_t* colors, int count, unsigned char* out) {
  // Four pixels (12 bytes) as three 4-byte stores, then the rest one by one.
  int x = 0;
  for (; x + 4 <= count; x += 4) {
    const uint32_t c0 = colors[x], c1 = colors[x + 1], c2 = colors[x + 2], c3 = colors[x + 3];
    const uint32_t words[3] = {c0 | c1 << 24, c1 >> 8 | c2 << 16, c2 >> 16 | c3 << 8};
    std::memcpy(out + 3 * x, words, 12);
  }
  for (; x < count; ++x) {
    out[3 * x + 0] = static_cast<unsigned char>(colors[x]);
    out[3 * x + 1] = static_cast<unsigned char>(colors[x] >> 8);
    out[3 * x + 2] = static_cast<unsigned char>(colors[x] >> 16);
  }
}

ZRENDER_AVX2 void packBgrAvx2(const uint32_t* colors, int count, unsigned char* out) {
  // Each 128-bit half packs its four pixels into its low 12 bytes; the two halves are stored
  // 12 bytes apart, each store writing 4 bytes past its pixels that the next store (or the
  // scalar tail) overwrites: so the vector loop stops 2 pixels before the end.
  int x = 0;
  for (; x + 10 <= count; x += 8) {
    const __m256i packed =
        squeezeBgr(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(colors + x)));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + 3 * x), _mm256_castsi256_si128(packed));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + 3 * x + 12),
                     _mm256_extracti128_si256(packed, 1));
  }
  packBgrScalar(colors + x, count - x, out + 3 * x);
}

RunEndFunction runEnd() {
  return cpuHasAvx2() ? runEndAvx2 : runEndScalar;
}

PackBgrFunction packBgr() {
  return cpuHasAvx2() ? packBgrAvx2 : packBgrScalar;
}

}  // namespace zrender
