#include "zrender/base/CpuFeatures.hpp"

namespace zrender {

bool cpuHasAvx2() {
  return __builtin_cpu_supports("avx2");
}

bool cpuHasAvx512() {
  return __builtin_cpu_supports("avx512f");
}

}  // namespace zrender
