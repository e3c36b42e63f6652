#include "zrender/base/CpuFeatures.hpp"

#include <cpuid.h>

namespace zrender {

bool cpuHasAvx2() {
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}

bool cpuGathersQuickly() {
  return cpuHasAvx2() && __builtin_cpu_is("intel");
}

bool cpuFillsWithoutReading() {
  // Asked once: in a virtual machine each CPUID instruction is a trip to the hypervisor.
  static const bool fills = [] {
    constexpr unsigned kErms = 1u << 9;  // enhanced rep movsb/stosb: CPUID leaf 7, EBX
    unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
    const bool erms = __get_cpuid_count(7, 0, &eax, &ebx, &ecx, &edx) && (ebx & kErms) != 0;
    return erms && __builtin_cpu_is("intel");
  }();
  return fills;
}

}  // namespace zrender
