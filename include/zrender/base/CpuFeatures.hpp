#pragma once

// Marks a function compiled for AVX2 (the build targets plain x86-64): call it only when
// cpuHasAvx2().
#define ZRENDER_AVX2 __attribute__((target("avx2")))
// The same for AVX-512 (F): call it only when cpuHasAvx512().
#define ZRENDER_AVX512 __attribute__((target("avx512f")))

namespace zrender {

// Whether this CPU runs AVX2 code: the vector pixel loops are used only then, and they give the
// same bits as their scalar versions (each is tested against its scalar twin).
bool cpuHasAvx2();
// Whether this CPU runs AVX-512F code (the shading's sixteen-lane loops, also tested against
// their scalar twins).
bool cpuHasAvx512();

}  // namespace zrender
