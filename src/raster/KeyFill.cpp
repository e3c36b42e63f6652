#include "zrender/raster/KeyFill.hpp"

#include <algorithm>

#include "zrender/base/CpuFeatures.hpp"

namespace zrender {

void fillKeysPlain(DepthKey* keys, size_t count, DepthKey key) {
  std::fill(keys, keys + count, key);
}

void fillKeysByStrings(DepthKey* keys, size_t count, DepthKey key) {
  asm volatile("rep stosq" : "+D"(keys), "+c"(count) : "a"(key) : "memory");
}

void fillKeys(DepthKey* keys, size_t count, DepthKey key) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  // The sanitizers do not see the writes of an asm statement: there, writes they can check.
  constexpr bool kSanitized = true;
#else
  constexpr bool kSanitized = false;
#endif
  if (!kSanitized && cpuFillsWithoutReading())
    fillKeysByStrings(keys, count, key);
  else
    fillKeysPlain(keys, count, key);
}

}  // namespace zrender
