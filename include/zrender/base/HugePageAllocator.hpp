#pragma once

#include <cstddef>
#include <cstdint>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include "zrender/base/UninitializedAllocator.hpp"

namespace zrender {

// An allocator for big arrays read and written all over (the frame buffer: 26 MB at
// 1800 x 1800): blocks of 2 MiB and more come straight from mmap, marked for transparent huge
// pages where the system grants them on request (Debian's default, "madvise"), so that pixel
// loops that jump around the image miss the TLB less (every algorithm's raster measured faster:
// docs/performance.md). Straight from mmap because only pages first touched after the
// advice become huge, and malloc may return memory it has touched before. Smaller blocks come
// from operator new. Like UninitializedAllocator, resize() leaves new elements of trivial types
// uninitialized: the owner writes them, and the first write to a page is what faults it in
// (the kernel zeroes it then), so writing them on several threads spreads that cost.
template <class T>
struct HugePageAllocator : UninitializedAllocator<T> {
  using value_type = T;
  template <class U>
  struct rebind {
    using other = HugePageAllocator<U>;
  };
  static constexpr std::size_t kHugePage = std::size_t(1) << 21;  // bytes

  static std::size_t wholePages(std::size_t bytes) {
    return (bytes + kHugePage - 1) & ~(kHugePage - 1);
  }

  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) {}

  T* allocate(std::size_t n) {
    if (n > (std::size_t(-1) - 2 * kHugePage) / sizeof(T)) throw std::bad_alloc();
    const std::size_t bytes = n * sizeof(T);
#if defined(__linux__)
    if (bytes >= kHugePage) {
      // Whole huge pages, mapped with one of slack, then trimmed to start on a huge page
      // boundary (only whole, aligned huge pages can be huge).
      const std::size_t used = wholePages(bytes);
      const std::size_t mapped = used + kHugePage;
      void* p = mmap(nullptr, mapped, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
      if (p == MAP_FAILED) throw std::bad_alloc();
      char* const start = static_cast<char*>(p);
      char* const aligned = reinterpret_cast<char*>(
          (reinterpret_cast<std::uintptr_t>(start) + kHugePage - 1) & ~(kHugePage - 1));
      if (aligned != start) munmap(start, std::size_t(aligned - start));
      const std::size_t tail = mapped - std::size_t(aligned - start) - used;
      if (tail) munmap(aligned + used, tail);
      madvise(aligned, used, MADV_HUGEPAGE);  // a hint: without it the pages are just small
      return reinterpret_cast<T*>(aligned);
    }
#endif
    return static_cast<T*>(::operator new(bytes));
  }
  void deallocate(T* p, std::size_t n) {
#if defined(__linux__)
    if (n * sizeof(T) >= kHugePage) {
      munmap(p, wholePages(n * sizeof(T)));
      return;
    }
#endif
    ::operator delete(p);
  }
};

template <class T, class U>
bool operator==(const HugePageAllocator<T>&, const HugePageAllocator<U>&) {
  return true;
}
template <class T, class U>
bool operator!=(const HugePageAllocator<T>&, const HugePageAllocator<U>&) {
  return false;
}

}  // namespace zrender
