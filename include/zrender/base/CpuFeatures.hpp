#pragma once

// Marks a function compiled for AVX2 (the build targets plain x86-64): call it only when
// cpuHasAvx2().
#define ZRENDER_AVX2 __attribute__((target("avx2")))

namespace zrender {

// Whether this CPU runs AVX2 code: the vector pixel loops are used only then, and they give the
// same bits as their scalar versions (each is tested against its scalar twin).
bool cpuHasAvx2();

}  // namespace zrender
