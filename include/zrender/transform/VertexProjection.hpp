#pragma once

#include <cstdint>

#include "zrender/raster/RasterRules.hpp"
#include "zrender/scene/Transforms.hpp"

namespace zrender {

// The per-vertex part of the transform (docs/design.md, Camera and transforms and Rasterization
// rules): model to clip space, the outcode, window coordinates and snapping. A scalar version (the
// reference) and an AVX2 one, four vertices at a time, doing the same IEEE operations, as the pixel
// loops do (TriangleFill.hpp).

// Outcode bits of a vertex.
enum VertexCode : uint32_t {
  kLeft = 1,
  kRight = 2,
  kBelow = 4,
  kAbove = 8,
  kNear = 16,
  kFar = 32,        // outside that plane
  kNotFinite = 64,  // a clip coordinate is NaN or infinite: faces using it are skipped
  kGuard = 128,     // inside near/far but beyond the guard band: needs the 2D clip
};
constexpr uint32_t kNeedsClip = kNear | kFar | kGuard | kNotFinite;

// What every face using a vertex (of one instance) reads first, kept small (16 bytes) so that
// the transformer's array of them stays in cache: faces reach their vertices in no particular
// order. The window position lives apart and is read only by faces that survive culling.
struct VertexState {
  FixedPoint snapped{0, 0};  // 1/256 sample units; valid when `code` has no kNeedsClip bit
  uint32_t code = 0;         // VertexCode bits
  uint32_t frame = 0;        // the frame the vertex was computed in (FaceTransformer)
};

// The frame's constants of the projection.
struct VertexViewport {
  int width = 0, height = 0;  // pixels
  int scale = 1;              // samples per pixel side: 1, or 2 for MSAA 4
};

// Projects `position` (model space) by `mvp` (model to clip space): sets state.code and
// state.frame; `window` (pixels right, pixels down, depth 0..1) unless the code has kNear, kFar
// or kNotFinite; state.snapped unless it has a kNeedsClip bit. Fields it does not set keep
// their values.
void projectVertex(const Mat4& mvp, const Vec3& position, const VertexViewport& viewport,
                   uint32_t frame, VertexState& state, Vec3& window);

// The same for four vertices of one instance, with bit-identical results in the fields
// projectVertex sets (the others get unspecified values). Call only when cpuHasAvx2().
void projectVertices4Avx2(const Mat4& mvp, const Vec3* const positions[4],
                          const VertexViewport& viewport, uint32_t frame, VertexState* states,
                          Vec3* windows);

}  // namespace zrender
