#include "zrender/measure/CullingBound.hpp"

#include <memory>
#include <vector>

#include "zrender/base/Median.hpp"
#include "zrender/render/Renderer.hpp"
#include "zrender/visibility/OctreeAlgorithm.hpp"

namespace zrender {

CullingBound measureCullingBound(const Scene& scene, const Camera& camera, int repeat,
                                 uint32_t leafFaces) {
  CullingBound bound;
  Renderer all(scene, "zbuffer");
  Renderer visibleOnly(scene, "zbuffer");
  Renderer octree(scene, std::make_unique<OctreeAlgorithm>(leafFaces));
  Renderer leafBound(scene, std::make_unique<OctreeAlgorithm>(leafFaces));
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

  auto holdsVisibleFace = [&visible](const uint32_t* faceIds, uint32_t count) {
    for (uint32_t i = 0; i < count; ++i)
      if (visible[faceIds[i]]) return true;
    return false;
  };
  // The leaves the octree draws, counted in a frame of its own (the hook is not free).
  auto& octreeAlgorithm = dynamic_cast<OctreeAlgorithm&>(octree.algorithm());
  octreeAlgorithm.skipLeaves([&bound](const uint32_t*, uint32_t) {
    ++bound.octreeLeavesDrawn;
    return false;
  });
  octree.renderFrame(camera);
  octreeAlgorithm.skipLeaves(nullptr);
  dynamic_cast<OctreeAlgorithm&>(leafBound.algorithm())
      .skipLeaves([&](const uint32_t* faceIds, uint32_t count) {
        return !holdsVisibleFace(faceIds, count);
      });
  for (const OctreeNode& node : octreeAlgorithm.octree().nodes())
    if (node.childMask == 0)
      bound.visibleLeaves += holdsVisibleFace(
          octreeAlgorithm.octree().faces().data() + node.faceBegin, node.faceEnd - node.faceBegin);

  std::vector<double> frame, raster, visibleRaster, octreeFrame, leafFrame, leafTransform,
      leafRaster;
  for (int i = 0; i < repeat; ++i) {
    const FrameTimings a = all.renderFrame(camera);
    frame.push_back(a.frameMs());
    raster.push_back(a.rasterMs);
    visibleRaster.push_back(visibleOnly.renderFrame(camera).rasterMs);
    octreeFrame.push_back(octree.renderFrame(camera).frameMs());
    const FrameTimings l = leafBound.renderFrame(camera);
    leafFrame.push_back(l.frameMs());
    leafTransform.push_back(l.transformMs);
    leafRaster.push_back(l.rasterMs);
  }
  bound.frameMs = median(frame);
  bound.rasterMs = median(raster);
  bound.visibleRasterMs = median(visibleRaster);
  bound.octreeFrameMs = median(octreeFrame);
  bound.leafBoundFrameMs = median(leafFrame);
  bound.leafBoundTransformMs = median(leafTransform);
  bound.leafBoundRasterMs = median(leafRaster);
  bound.identical =
      identicalFrames(all.buffer(), all.color(), visibleOnly.buffer(), visibleOnly.color());
  bound.leafBoundIdentical =
      identicalFrames(all.buffer(), all.color(), leafBound.buffer(), leafBound.color());
  return bound;
}

}  // namespace zrender
