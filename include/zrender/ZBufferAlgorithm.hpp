#pragma once

#include <vector>

#include "zrender/VisibilityAlgorithm.hpp"

namespace zrender {

// The classic z-buffer: for each triangle, every sample of its bounding box is tested for
// coverage and depth. Triangles are visited band by band (see the .cpp) for cache locality.
class ZBufferAlgorithm : public VisibilityAlgorithm {
 public:
  std::string name() const override { return "zbuffer"; }
  void render(FrameInput& input, FrameBuffer& fb, RenderStats& stats) override;

 private:
  // Scratch reused from frame to frame: each triangle's band, the triangles sorted by band.
  std::vector<uint32_t> band_, bandStart_, cursor_;
  std::vector<ScreenTriangle> sorted_;
};

}  // namespace zrender
