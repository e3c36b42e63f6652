#include "zrender/measure/CullingBound.hpp"

#include <memory>
#include <vector>

#include "zrender/base/Median.hpp"
#include "zrender/measure/KeptTriangles.hpp"
#include "zrender/measure/SkippedBatches.hpp"
#include "zrender/render/Renderer.hpp"
#include "zrender/visibility/OctreeAlgorithm.hpp"
#include "zrender/visibility/ZBufferAlgorithm.hpp"

namespace zrender {

CullingBound measureCullingBound(const Scene& scene, const Camera& camera, int repeat,
                                 uint32_t leafFaces) {
  CullingBound bound;
  Renderer all(scene, "zbuffer");
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
  Renderer visibleOnly(scene, std::make_unique<ZBufferAlgorithm>(),
                       [&visible](GeometrySource& transform, FaceBatches) {
                         return std::make_unique<KeptTriangles>(
                             transform,
                             [&visible](const ScreenTriangle& t) { return bool(visible[t.id]); });
                       });

  // The octree as it is (counting the leaves it draws in a frame of its own), and the octree
  // skipping the leaves that hold no visible face.
  size_t octreeLeaves = 0, boundLeaves = 0;
  Renderer octree(scene, std::make_unique<OctreeAlgorithm>(leafFaces),
                  [&octreeLeaves](GeometrySource& transform, FaceBatches) {
                    return std::make_unique<SkippedBatches>(transform, std::vector<bool>(),
                                                            octreeLeaves);
                  });
  Renderer leafBound(scene, std::make_unique<OctreeAlgorithm>(leafFaces),
                     [&](GeometrySource& transform, FaceBatches batches) {
                       std::vector<bool> skip;
                       for (size_t b = 0; b + 1 < batches.starts->size(); ++b) {
                         bool holdsVisible = false;
                         for (uint32_t i = (*batches.starts)[b]; i < (*batches.starts)[b + 1]; ++i)
                           holdsVisible = holdsVisible || visible[(*batches.faces)[i]];
                         skip.push_back(!holdsVisible);
                         bound.visibleLeaves += holdsVisible;
                       }
                       return std::make_unique<SkippedBatches>(transform, std::move(skip),
                                                               boundLeaves);
                     });
  octree.renderFrame(camera);
  bound.octreeLeavesDrawn = octreeLeaves;

  std::vector<double> frame, raster, visibleRaster, octreeFrame, leafFrame, leafTransform,
      leafRaster;
  for (int i = 0; i < repeat; ++i) {
    const FrameTimings a = all.renderFrame(camera);
    frame.push_back(a.frameMs());
    raster.push_back(a.rasterMs());
    visibleRaster.push_back(visibleOnly.renderFrame(camera).rasterMs());
    octreeFrame.push_back(octree.renderFrame(camera).frameMs());
    const FrameTimings l = leafBound.renderFrame(camera);
    leafFrame.push_back(l.frameMs());
    leafTransform.push_back(l.transformMs);
    leafRaster.push_back(l.rasterMs());
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
