#pragma once

#include <string>

namespace zrender {

// What this zrender was built from, fixed when CMake configured the build.
struct BuildInfo {
  std::string version;    // "0.1.0"
  std::string commit;     // the git commit's full hash, "" when not built from a git checkout
  std::string compiler;   // "GNU 12.2.0"
  std::string buildType;  // "Release"
};

BuildInfo buildInfo();

}  // namespace zrender
