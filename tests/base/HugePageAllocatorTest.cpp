// The allocator of big buffers (HugePageAllocator): values survive the move from operator new
// blocks to mapped ones and back, and an impossible size throws std::bad_alloc.

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <new>
#include <vector>

#include "zrender/base/HugePageAllocator.hpp"

namespace zrender {
namespace {

TEST(HugePageAllocator, VectorsKeepTheirValuesAcrossBothKindsOfBlock) {
  // Grows from operator new blocks into mapped ones; every value must move along.
  std::vector<uint64_t, HugePageAllocator<uint64_t>> v;
  for (uint64_t i = 0; i < 600000; ++i) v.push_back(i * 2654435761u);
  for (uint64_t i = 0; i < v.size(); ++i) ASSERT_EQ(v[i], i * 2654435761u);
  v.resize(10);
  v.shrink_to_fit();  // back to a small block
  EXPECT_EQ(v[9], uint64_t(9) * 2654435761u);
  HugePageAllocator<uint64_t> allocator;
  EXPECT_THROW(allocator.allocate(std::size_t(-1) / 8), std::bad_alloc);
}

}  // namespace
}  // namespace zrender
