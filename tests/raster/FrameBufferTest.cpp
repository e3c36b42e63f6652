// The visibility buffer (FrameBuffer): big buffers start on a huge page and copy like vectors.

#include <gtest/gtest.h>

#include <cstdint>

#include "zrender/base/HugePageAllocator.hpp"
#include "zrender/raster/FrameBuffer.hpp"
#include "zrender/raster/RasterRules.hpp"

namespace zrender {
namespace {

TEST(FrameBuffer, BigBuffersStartOnAHugePageAndCopyLikeVectors) {
  FrameBuffer big;
  big.resize(1800, 1800);
#if defined(__linux__)
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(big.data()) % HugePageAllocator<DepthKey>::kHugePage,
            0u);
#endif
  big.clear();
  big.row(1799)[1799] = makeDepthKey(0.5f, 7);
  FrameBuffer copy = big;
  EXPECT_TRUE(copy == big);
  copy.row(0)[0] = makeDepthKey(0.25f, 3);
  EXPECT_FALSE(copy == big);
  EXPECT_EQ(big.row(1799)[1799], makeDepthKey(0.5f, 7));

  FrameBuffer small;  // below a huge page: operator new
  small.resize(8, 8);
  small.clear();
  FrameBuffer smallCopy = small;
  EXPECT_TRUE(smallCopy == small);
}

}  // namespace
}  // namespace zrender
