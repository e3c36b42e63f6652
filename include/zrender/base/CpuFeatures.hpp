#pragma once

// Marks a function compiled for AVX2 and FMA (the build targets plain x86-64): call it only
// when cpuHasAvx2(). The build keeps -ffp-contract=off, so the compiler fuses a multiply and an
// add only where the code asks for it (_mm256_fmadd_ps, std::fma).
#define ZRENDER_AVX2 __attribute__((target("avx2,fma")))

namespace zrender {

// Whether this CPU runs AVX2 and FMA code: the vector pixel and shading loops are used only
// then, and they give the same bits as their scalar versions (each is tested against its
// scalar twin). Every CPU with AVX2 so far also has FMA.
bool cpuHasAvx2();
// Whether this CPU's AVX2 gathers are quick: about a cycle per element on Intel's cores, where
// eight gathered texels beat eight loads and the shuffles that combine them; AMD's (Zen 3: 39
// micro-ops for eight elements) do not (docs/performance.md, Shading).
bool cpuGathersQuickly();
// Whether `rep stos` writes whole cache lines without reading them first: Intel's fast string
// stores (ERMS). Measured on Intel only; elsewhere plain stores fill memory
// (docs/performance.md, The z-buffer's clear).
bool cpuFillsWithoutReading();

}  // namespace zrender
