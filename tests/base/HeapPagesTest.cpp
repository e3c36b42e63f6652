// The heap marked for huge pages (useHugePagesForHeap): in a fresh process, as zrender's main()
// calls it, a block below 32 MiB then lies in a mapping marked "hg" (MADV_HUGEPAGE), which a
// plain anonymous mapping is not.

#include <gtest/gtest.h>
#include <sys/mman.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include "zrender/base/HeapPages.hpp"

namespace zrender {
namespace {

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
TEST(HeapPages, NotMarkedUnderASanitizersMalloc) {
  GTEST_SKIP() << "a sanitizer's malloc has no heap to mark";
}
#else
// The VmFlags line of /proc/self/smaps for the mapping that holds `p` ("" if none does).
std::string vmFlagsOf(const void* p) {
  std::ifstream smaps("/proc/self/smaps");
  const auto address = reinterpret_cast<uintptr_t>(p);
  bool inside = false;
  std::string line;
  while (std::getline(smaps, line)) {
    uintptr_t begin = 0, end = 0;
    char dash = 0;
    std::istringstream range(line);
    if (range >> std::hex >> begin >> dash >> end && dash == '-') {
      inside = begin <= address && address < end;
    } else if (inside && line.rfind("VmFlags:", 0) == 0) {
      return line;
    }
  }
  return "";
}

bool markedHuge(const void* p) {
  return vmFlagsOf(p).find(" hg") != std::string::npos;
}

TEST(HeapPages, BlocksOfTheHeapLieInHugePages) {
  void* plain =
      mmap(nullptr, size_t(4) << 20, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  ASSERT_NE(plain, MAP_FAILED);
  ASSERT_FALSE(vmFlagsOf(plain).empty());
  EXPECT_FALSE(markedHuge(plain));
  munmap(plain, size_t(4) << 20);

  // In a fresh process (the statement runs in a child that executes this test alone), whose
  // heap has nothing freed yet that a block could reuse.
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        if (!useHugePagesForHeap()) std::exit(1);
        // Its first bytes may lie below the first whole huge page of the marked part.
        auto* block = static_cast<char*>(std::malloc(size_t(8) << 20));
        std::exit(block && markedHuge(block + (size_t(4) << 20)) ? 0 : 2);
      },
      ::testing::ExitedWithCode(0), "");
}
#endif

}  // namespace
}  // namespace zrender
