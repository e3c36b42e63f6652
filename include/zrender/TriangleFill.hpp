#pragma once

#include <cstdint>

#include "zrender/FrameBuffer.hpp"
#include "zrender/RasterRules.hpp"
#include "zrender/RenderStats.hpp"

namespace zrender {

// Depth-tests and writes every sample of a set-up triangle: the pixel loop of the z-buffer,
// shared by the triangle-based algorithms. Runs fillTriangleAvx2 where the CPU has AVX2,
// else fillTriangleScalar; both test the same samples with the same bits (RasterRules.hpp).
void fillTriangle(const TriangleSetup& s, const DepthPlane& plane, uint32_t faceId, FrameBuffer& fb,
                  RenderStats& stats);

// One sample at a time: the reference the vector version is tested against.
void fillTriangleScalar(const TriangleSetup& s, const DepthPlane& plane, uint32_t faceId,
                        FrameBuffer& fb, RenderStats& stats);

// Four samples at a time. Call only when cpuHasAvx2() (CpuFeatures.hpp).
void fillTriangleAvx2(const TriangleSetup& s, const DepthPlane& plane, uint32_t faceId,
                      FrameBuffer& fb, RenderStats& stats);

}  // namespace zrender
