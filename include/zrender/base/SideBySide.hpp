#pragma once

#include <exception>

#include "zrender/base/Threads.hpp"

namespace zrender {

// Runs first() and second(), two independent jobs: side by side on `threads` when it has more
// than one, else in order (second() only if first() returned). Either way the caller sees what
// running them in order would throw: first()'s exception, else second()'s. So second() may run
// after a failure of first() that would have stopped it; it must keep its effects (warnings,
// results) to itself until both have returned.
template <typename First, typename Second>
void sideBySide(const Threads* threads, const First& first, const Second& second) {
  if (!threads || !threads->parallel()) {
    first();
    second();
    return;
  }
  std::exception_ptr errors[2];
  threads->forEach(2, [&](size_t job) {
    try {
      if (job == 0) {
        first();
      } else {
        second();
      }
    } catch (...) {
      errors[job] = std::current_exception();
    }
  });
  for (const std::exception_ptr& error : errors)
    if (error) std::rethrow_exception(error);
}

}  // namespace zrender
