#pragma once

#include <cstddef>

#include "zrender/base/CpuFeatures.hpp"

namespace zrender {

// BGR pixels (OpenCV's order) as RGB (PNG's): `pixels` pixels from `in` to out[0, 3 pixels).
// The AVX2 version (call only when cpuHasAvx2()) moves five pixels a time with a byte shuffle
// and gives the same bytes as the scalar one. `in` and `out` do not overlap.
void bgrToRgbScalar(const unsigned char* in, unsigned char* out, size_t pixels);
ZRENDER_AVX2 void bgrToRgbAvx2(const unsigned char* in, unsigned char* out, size_t pixels);

// The one of the two this CPU runs.
using BgrToRgb = void (*)(const unsigned char*, unsigned char*, size_t);
BgrToRgb bgrToRgb();

}  // namespace zrender
