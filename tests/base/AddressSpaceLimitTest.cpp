// AddressSpaceLimit: inside its scope an allocation past the budget throws std::bad_alloc and
// one within it does not; afterwards the process's limit is what it was.

#include <gtest/gtest.h>
#include <sys/resource.h>

#include <new>

#include "zrender/base/AddressSpaceLimit.hpp"

namespace zrender {
namespace {

// Allocates and frees `bytes` (untouched); the volatile pointer keeps the pair from being elided.
bool allocates(size_t bytes) {
  try {
    char* volatile block = new char[bytes];
    delete[] block;
    return true;
  } catch (const std::bad_alloc&) {
    return false;
  }
}

TEST(AddressSpaceLimit, AllocationsPastTheBudgetFailAndTheLimitComesBack) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "the sanitizers' operator new ends the process instead of throwing";
#endif
  rlimit before{};
  ASSERT_EQ(getrlimit(RLIMIT_AS, &before), 0);
  ASSERT_GT(mappedBytes(), 0u);
  constexpr size_t kGiB = size_t(1) << 30;
  {
    const AddressSpaceLimit limit(kGiB / 4);
    ASSERT_TRUE(limit.active());
    EXPECT_FALSE(allocates(kGiB));
    EXPECT_TRUE(allocates(kGiB / 64));
  }
  rlimit after{};
  ASSERT_EQ(getrlimit(RLIMIT_AS, &after), 0);
  EXPECT_EQ(after.rlim_cur, before.rlim_cur);
  EXPECT_EQ(after.rlim_max, before.rlim_max);
  EXPECT_TRUE(allocates(kGiB));
}

}  // namespace
}  // namespace zrender
