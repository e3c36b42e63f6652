#include "zrender/base/AddressSpaceLimit.hpp"

#include <unistd.h>

#include <cstdio>

namespace zrender {

size_t mappedBytes() {
  std::FILE* statm = std::fopen("/proc/self/statm", "r");
  if (statm == nullptr) return 0;
  unsigned long pages = 0;
  const bool read = std::fscanf(statm, "%lu", &pages) == 1;
  std::fclose(statm);
  const long pageSize = sysconf(_SC_PAGESIZE);
  return read && pageSize > 0 ? size_t(pages) * size_t(pageSize) : 0;
}

AddressSpaceLimit::AddressSpaceLimit(size_t extraBytes) {
  const size_t mapped = mappedBytes();
  if (mapped == 0 || getrlimit(RLIMIT_AS, &saved_) != 0) return;
  const rlim_t wanted =
      extraBytes > RLIM_INFINITY - 1 - mapped ? RLIM_INFINITY - 1 : rlim_t(mapped + extraBytes);
  if (saved_.rlim_cur != RLIM_INFINITY && saved_.rlim_cur <= wanted) return;
  if (saved_.rlim_max != RLIM_INFINITY && saved_.rlim_max < wanted) return;
  rlimit lowered = saved_;
  lowered.rlim_cur = wanted;
  set_ = setrlimit(RLIMIT_AS, &lowered) == 0;
}

AddressSpaceLimit::~AddressSpaceLimit() {
  if (set_) setrlimit(RLIMIT_AS, &saved_);
}

}  // namespace zrender
