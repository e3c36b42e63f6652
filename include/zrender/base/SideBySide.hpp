#pragma once

#include <cstddef>
#include <exception>
#include <vector>

#include "zrender/base/Threads.hpp"

namespace zrender {

// Runs job(0) to job(n - 1), independent jobs: side by side on `threads` when it has more than
// one, else in order (stopping at the first that throws). Either way the caller sees what
// running them in order would throw: the exception of the first job, by index, that threw. So a
// job may run after a failure of an earlier one that would have stopped it; it must keep its
// effects (warnings, results) to itself until all have returned.
template <typename Job>
void sideBySide(const Threads* threads, size_t n, const Job& job) {
  if (!threads || !threads->parallel()) {
    for (size_t i = 0; i < n; ++i) job(i);
    return;
  }
  std::vector<std::exception_ptr> errors(n);
  threads->forEach(n, [&](size_t i) {
    try {
      job(i);
    } catch (...) {
      errors[i] = std::current_exception();
    }
  });
  for (const std::exception_ptr& error : errors)
    if (error) std::rethrow_exception(error);
}

}  // namespace zrender
