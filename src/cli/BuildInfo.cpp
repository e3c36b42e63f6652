#include "zrender/cli/BuildInfo.hpp"

// Defined for this file only by CMakeLists.txt, so that a new commit recompiles it alone.
#ifndef ZRENDER_COMMIT
#define ZRENDER_COMMIT ""
#endif

namespace zrender {

BuildInfo buildInfo() {
  return BuildInfo{ZRENDER_VERSION, ZRENDER_COMMIT, ZRENDER_COMPILER, ZRENDER_BUILD_TYPE};
}

}  // namespace zrender
