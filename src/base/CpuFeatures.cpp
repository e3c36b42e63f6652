#include "zrender/base/CpuFeatures.hpp"

namespace zrender {

bool cpuHasAvx2() {
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}

bool cpuGathersQuickly() {
  return cpuHasAvx2() && __builtin_cpu_is("intel");
}

}  // namespace zrender
