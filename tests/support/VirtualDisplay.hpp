#pragma once

// A virtual X display for the tests of `zrender view`: an Xvfb server of the test's own.

#include <sys/types.h>
#include <string>

#include "support/TestSupport.hpp"

namespace zrender::test {

// Starts Xvfb on a display number it picks itself among the free ones (-displayfd), so tests
// running side by side never share one. The destructor stops it and waits for it; if the test
// process dies first, the kernel sends Xvfb SIGTERM (PR_SET_PDEATHSIG), so none is left behind.
class VirtualDisplay {
 public:
  VirtualDisplay();
  ~VirtualDisplay();
  VirtualDisplay(const VirtualDisplay&) = delete;
  VirtualDisplay& operator=(const VirtualDisplay&) = delete;

  // ":N", or empty when Xvfb could not start (then `error` says why).
  const std::string& name() const { return name_; }
  const std::string& error() const { return error_; }

  // The environment of a program run on this display: DISPLAY, and where the suite runs under
  // AddressSanitizer (tools/sanitize.sh) two of its checks off for the libraries that draw the
  // window, not zrender's code: leaks, since Qt keeps caches it frees only at exit, and strict
  // string checks, since libxkbcommon-x11 strndup()s key names that are not NUL-terminated.
  Environment environment() const;

 private:
  pid_t pid_ = -1;
  std::string name_, error_;
};

}  // namespace zrender::test
