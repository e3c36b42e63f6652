#pragma once

#include <vector>

#include "zrender/raster/TriangleBands.hpp"
#include "zrender/visibility/VisibilityAlgorithm.hpp"

namespace zrender {

// The classic z-buffer: for each triangle, every sample of its bounding box is tested for
// coverage and depth. Triangles are visited band by band (TriangleBands) for cache locality;
// with several threads, the bands are drawn at once, each by one thread.
class ZBufferAlgorithm : public VisibilityAlgorithm {
 public:
  std::string name() const override { return "zbuffer"; }
  void render(FrameInput& input, FrameBuffer& fb, RenderStats& stats) override;

 private:
  void renderBands(FrameInput& input, FrameBuffer& fb, RenderStats& stats);

  TriangleBands bands_;
  std::vector<RenderStats> bandStats_;       // renderBands(): each band's counters
  std::vector<FrameGeometry> partGeometry_;  // renderBands(): the frame's geometry
  FaceParts parts_;                          // views of it
};

}  // namespace zrender
