#pragma once

#include <cstdint>

#include "zrender/raster/FrameBuffer.hpp"
#include "zrender/raster/RasterRules.hpp"
#include "zrender/raster/RenderStats.hpp"

namespace zrender {

// The pixel loops of the z-buffer family, each in a scalar version (the reference) and an AVX2
// one (four samples at a time, the same samples and the same bits: RasterRules.hpp). Callers
// take the fastest this CPU runs once (triangleFill(), spanFill()) and call it per primitive.

// Depth-tests and writes every sample of a set-up triangle: the pixel loop of the z-buffer,
// shared by the triangle-based algorithms. One sample at a time.
void fillTriangleScalar(const TriangleSetup& s, const DepthPlane& plane, uint32_t faceId,
                        FrameBuffer& fb, RenderStats& stats);

// Four samples at a time. Call only when cpuHasAvx2() (CpuFeatures.hpp).
void fillTriangleAvx2(const TriangleSetup& s, const DepthPlane& plane, uint32_t faceId,
                      FrameBuffer& fb, RenderStats& stats);

// Depth-tests samples [left, right) of one row of keys for a face with depth `plane`, whose
// rowBase() for that row is given, and writes the winners: the span loop of the scan-line
// z-buffer. Returns the number written. The row must have FrameBuffer::kPadding writable keys
// after its last sample (a vector block may run past `right`, writing back what it read).
uint64_t fillSpanScalar(DepthKey* row, int left, int right, const DepthPlane& plane, double rowBase,
                        uint32_t faceId);
uint64_t fillSpanAvx2(DepthKey* row, int left, int right, const DepthPlane& plane, double rowBase,
                      uint32_t faceId);

using TriangleFillFunction = void (*)(const TriangleSetup&, const DepthPlane&, uint32_t,
                                      FrameBuffer&, RenderStats&);
using SpanFillFunction = uint64_t (*)(DepthKey*, int, int, const DepthPlane&, double, uint32_t);

// The AVX2 versions where the CPU has AVX2, else the scalar ones.
TriangleFillFunction triangleFill();
SpanFillFunction spanFill();

}  // namespace zrender
