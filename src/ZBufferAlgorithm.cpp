#include "zrender/ZBufferAlgorithm.hpp"

#include "zrender/TriangleFill.hpp"

namespace zrender {

void ZBufferAlgorithm::render(FrameInput& input, FrameBuffer& fb, RenderStats& stats) {
  fb.clear();
  const FrameGeometry& g = input.geometry;
  TriangleSetup setup;
  for (const ScreenTriangle& t : g.triangles) {
    if (!setup.setup(t.v, fb.width(), fb.height())) continue;
    const ScreenFace& face = g.faces[t.face];
    ++stats.trianglesRasterized;
    fillTriangle(setup, face.plane, face.id, fb, stats);
  }
}

}  // namespace zrender
