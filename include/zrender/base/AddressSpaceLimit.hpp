#pragma once

#include <sys/resource.h>

#include <cstddef>

namespace zrender {

// Lowers the process's address-space limit (the soft RLIMIT_AS) to what it maps now plus
// `extraBytes`, for the object's lifetime, so that code which would map more (a third-party
// model reader looping on a damaged file) gets std::bad_alloc instead of the machine's memory.
// The limit is the whole process's: for code that runs while no other thread allocates. Does
// nothing where the mappings cannot be read or the limit is already that low.
class AddressSpaceLimit {
 public:
  explicit AddressSpaceLimit(size_t extraBytes);
  ~AddressSpaceLimit();
  AddressSpaceLimit(const AddressSpaceLimit&) = delete;
  AddressSpaceLimit& operator=(const AddressSpaceLimit&) = delete;
  bool active() const { return set_; }

 private:
  rlimit saved_{};
  bool set_ = false;
};

// The bytes the process maps now (VmSize, /proc/self/statm); 0 where it cannot be read.
size_t mappedBytes();

}  // namespace zrender
