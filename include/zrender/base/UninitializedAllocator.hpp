#pragma once

#include <memory>
#include <type_traits>
#include <utility>

namespace zrender {

// std::allocator, but resize() leaves new elements of trivial types uninitialized instead of
// zeroing them: for arrays that are grown and then written in full (a frame's geometry,
// joined from chunks by several threads), where zeroing first would be a pass over memory for
// nothing.
template <class T>
struct UninitializedAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = UninitializedAllocator<U>;
  };
  UninitializedAllocator() = default;
  template <class U>
  UninitializedAllocator(const UninitializedAllocator<U>&) noexcept {}

  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;  // default-initialized: indeterminate for trivial types
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

}  // namespace zrender
