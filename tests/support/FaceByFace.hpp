#pragma once

#include <cstdint>
#include <vector>

#include "zrender/raster/FrameGeometry.hpp"
#include "zrender/scene/Camera.hpp"
#include "zrender/scene/Scene.hpp"
#include "zrender/transform/FaceAssembler.hpp"
#include "zrender/transform/MeshLayout.hpp"

namespace zrender::test {

// The transform one face at a time: the reference that FaceTransformer's pulls (by instance,
// by batch) are tested against. Each corner is projected on its own by the scalar
// projectVertex, and the face assembled by the FaceAssembler every pull uses.
class FaceByFace {
 public:
  FaceByFace(const Scene& scene, int sampleScale, bool cull);
  FaceByFace(const Scene& scene, const Camera& camera, int sampleScale, bool cull);

  void beginFrame(const Camera& camera);
  // Appends face `faceId` (a global id: instance x faces + face) to `out`.
  void transformFace(uint32_t faceId, FrameGeometry& out);

 private:
  const Scene& scene_;
  MeshLayout layout_;
  FaceAssembler assembler_;
  VertexViewport viewport_;
  std::vector<Mat4> mvp_;
  std::vector<VertexState> state_;
  std::vector<Vec3> window_;
  std::vector<uint32_t> slot_, instance_, local_;
};

}  // namespace zrender::test
