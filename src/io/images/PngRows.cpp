#include "zrender/io/images/PngRows.hpp"

#include <immintrin.h>

namespace zrender {

void bgrToRgbScalar(const unsigned char* in, unsigned char* out, size_t pixels) {
  for (size_t i = 0; i < 3 * pixels; i += 3)
    out[i] = in[i + 2], out[i + 1] = in[i + 1], out[i + 2] = in[i];
}

ZRENDER_AVX2 void bgrToRgbAvx2(const unsigned char* in, unsigned char* out, size_t pixels) {
  // Sixteen bytes in, five pixels swapped and the sixteenth byte kept; the next store starts
  // at the sixteenth byte and writes it again. The loads stay within the row: a sixth pixel
  // must follow the five.
  const __m128i swap = _mm_setr_epi8(2, 1, 0, 5, 4, 3, 8, 7, 6, 11, 10, 9, 14, 13, 12, 15);
  size_t p = 0;
  for (; p + 6 <= pixels; p += 5) {
    const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(in + 3 * p));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + 3 * p), _mm_shuffle_epi8(v, swap));
  }
  bgrToRgbScalar(in + 3 * p, out + 3 * p, pixels - p);
}

BgrToRgb bgrToRgb() {
  return cpuHasAvx2() ? bgrToRgbAvx2 : bgrToRgbScalar;
}

}  // namespace zrender
