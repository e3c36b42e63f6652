#pragma once

#include "zrender/VisibilityAlgorithm.hpp"

namespace zrender {

// The classic z-buffer: for each triangle, every sample of its bounding box is tested for
// coverage and depth.
class ZBufferAlgorithm : public VisibilityAlgorithm {
 public:
  std::string name() const override { return "zbuffer"; }
  void render(FrameInput& input, FrameBuffer& fb, RenderStats& stats) override;
};

}  // namespace zrender
