#include "zrender/base/HeapPages.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include "zrender/base/HugePageAllocator.hpp"

#if defined(__GLIBC__)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace zrender {

bool useHugePagesForHeap() {
#if defined(__GLIBC__) && defined(MADV_HUGEPAGE)
  constexpr int kMmapThreshold = 32 << 20;  // bytes: glibc's largest on 64 bits
  constexpr int kTopPad = 128 << 20;        // bytes the heap grows by beyond a request
  constexpr uintptr_t kHugePage = HugePageAllocator<char>::kHugePage;
  if (mallopt(M_MMAP_THRESHOLD, kMmapThreshold) != 1 || mallopt(M_TOP_PAD, kTopPad) != 1 ||
      mallopt(M_TRIM_THRESHOLD, 2 * kTopPad) != 1)
    return false;  // another malloc (a sanitizer's): nothing to mark
  // A block bigger than what the heap has free makes it grow now, by the pad: the whole new
  // part is marked at once (a later growth of the heap would not inherit the mark).
  void* block = std::malloc(size_t(1) << 20);
  if (!block) return false;
  const auto first = (reinterpret_cast<uintptr_t>(block) + kHugePage - 1) & ~(kHugePage - 1);
  const auto top = reinterpret_cast<uintptr_t>(sbrk(0));
  bool marked = false;
  if (top > first)  // else the block did not come from the heap that sbrk grows
    marked = madvise(reinterpret_cast<void*>(first), size_t(top - first), MADV_HUGEPAGE) == 0;
  std::free(block);
  return marked;
#else
  return false;
#endif
}

}  // namespace zrender
