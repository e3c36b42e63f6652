// BGR rows as PNG's RGB (io/PngRows.hpp): the bytes swapped, and the AVX2 version's bytes the
// scalar one's at every width, the tail included.

#include <gtest/gtest.h>

#include <cstddef>
#include <random>
#include <vector>

#include "zrender/io/images/PngRows.hpp"

namespace zrender {
namespace {

TEST(PngRows, BgrBecomesRgb) {
  const unsigned char bgr[] = {1, 2, 3, 4, 5, 6};
  unsigned char rgb[6] = {};
  bgrToRgbScalar(bgr, rgb, 2);
  const unsigned char expected[] = {3, 2, 1, 6, 5, 4};
  EXPECT_EQ(std::vector<unsigned char>(rgb, rgb + 6),
            std::vector<unsigned char>(expected, expected + 6));
}

TEST(PngRows, Avx2GivesTheScalarBytes) {
  if (!cpuHasAvx2()) GTEST_SKIP() << "no AVX2 on this CPU";
  std::mt19937 rng(5);
  for (size_t pixels = 0; pixels <= 1801; pixels += pixels < 40 ? 1 : 589) {
    // Exactly the row's bytes, so that AddressSanitizer sees a read or write past them.
    std::vector<unsigned char> in(3 * pixels);
    for (unsigned char& b : in) b = static_cast<unsigned char>(rng());
    std::vector<unsigned char> scalar(3 * pixels), avx2(3 * pixels);
    bgrToRgbScalar(in.data(), scalar.data(), pixels);
    bgrToRgbAvx2(in.data(), avx2.data(), pixels);
    EXPECT_EQ(avx2, scalar) << pixels << " pixels";
  }
}

}  // namespace
}  // namespace zrender
