#include "zrender/CullingBound.hpp"

#include <vector>

#include "zrender/Renderer.hpp"
#include "zrender/Report.hpp"

namespace zrender {

CullingBound measureCullingBound(const Scene& scene, const Camera& camera, int repeat) {
  CullingBound bound;
  Renderer all(scene, "zbuffer");
  Renderer visibleOnly(scene, "zbuffer");
  all.renderFrame(camera);
  bound.triangles = all.geometry().triangles.size();

  // The faces that own a sample of the final buffer, by id.
  std::vector<bool> visible(scene.faceCount());
  const FrameBuffer& keys = all.buffer();
  for (size_t i = 0; i < keys.size(); ++i) {
    const uint32_t id = keyFaceId(keys.data()[i]);
    if (id == kBackgroundId || visible[id]) continue;
    visible[id] = true;
    ++bound.visibleFaces;
  }
  for (const ScreenTriangle& t : all.geometry().triangles) bound.visibleTriangles += visible[t.id];
  visibleOnly.keepTriangles([&visible](const ScreenTriangle& t) { return bool(visible[t.id]); });

  std::vector<double> frame, raster, visibleRaster;
  for (int i = 0; i < repeat; ++i) {
    const FrameTimings a = all.renderFrame(camera);
    frame.push_back(a.frameMs());
    raster.push_back(a.rasterMs);
    visibleRaster.push_back(visibleOnly.renderFrame(camera).rasterMs);
  }
  bound.frameMs = median(frame);
  bound.rasterMs = median(raster);
  bound.visibleRasterMs = median(visibleRaster);
  bound.identical =
      identicalFrames(all.buffer(), all.color(), visibleOnly.buffer(), visibleOnly.color());
  return bound;
}

}  // namespace zrender
