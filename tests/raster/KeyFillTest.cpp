// KeyFill: both ways of filling keys (std::fill and `rep stosq`) set exactly the keys asked, at
// any start and length, and FrameBuffer::clearRows clears exactly its rows.

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "zrender/raster/FrameBuffer.hpp"
#include "zrender/raster/KeyFill.hpp"
#include "zrender/raster/RasterRules.hpp"

namespace zrender {
namespace {

using FillFunction = void (*)(DepthKey*, size_t, DepthKey);

TEST(KeyFill, EveryWayFillsExactlyTheKeysAsked) {
  const DepthKey guard = makeDepthKey(0.25f, 12345);
  const struct {
    std::string name;
    FillFunction fill;
  } ways[] = {{"plain", fillKeysPlain}, {"strings", fillKeysByStrings}, {"chosen", fillKeys}};
  for (const auto& way : ways) {
    for (size_t start = 0; start < 9; ++start) {
      for (size_t count : {0u, 1u, 2u, 7u, 8u, 9u, 63u, 64u, 65u, 1000u, 100000u}) {
        std::vector<DepthKey> keys(start + count + 9, guard);
        way.fill(keys.data() + start, count, kClearKey);
        for (size_t i = 0; i < keys.size(); ++i) {
          const bool inside = i >= start && i < start + count;
          ASSERT_EQ(keys[i], inside ? kClearKey : guard)
              << way.name << ": start " << start << ", count " << count << ", key " << i;
        }
      }
    }
  }
}

TEST(FrameBuffer, ClearRowsClearsThoseRowsOnly) {
  FrameBuffer fb;
  fb.resize(37, 11);
  const DepthKey drawn = makeDepthKey(0.5f, 3);
  for (int y = 0; y < fb.height(); ++y)
    for (int x = 0; x < fb.width(); ++x) fb.row(y)[x] = drawn;
  fb.clearRows(4, 7);
  for (int y = 0; y < fb.height(); ++y)
    for (int x = 0; x < fb.width(); ++x)
      ASSERT_EQ(fb.row(y)[x], y >= 4 && y < 7 ? kClearKey : drawn) << x << ", " << y;
}

}  // namespace
}  // namespace zrender
