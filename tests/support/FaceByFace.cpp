#include "support/FaceByFace.hpp"

#include "zrender/transform/VertexProjection.hpp"

namespace zrender::test {

FaceByFace::FaceByFace(const Scene& scene, int sampleScale, bool cull)
    : scene_(scene), layout_(scene), assembler_(sampleScale, cull) {
  viewport_.scale = sampleScale;
}

FaceByFace::FaceByFace(const Scene& scene, const Camera& camera, int sampleScale, bool cull)
    : FaceByFace(scene, sampleScale, cull) {
  beginFrame(camera);
}

void FaceByFace::beginFrame(const Camera& camera) {
  viewport_.width = camera.width;
  viewport_.height = camera.height;
  mvp_.clear();
  for (uint32_t k = 0; k < scene_.instanceCount(); ++k)
    mvp_.push_back(camera.projection * camera.view * scene_.modelMatrix(k));
  assembler_.beginFrame(camera.width, camera.height, layout_.slotPositions(), mvp_);
}

void FaceByFace::transformFace(uint32_t faceId, FrameGeometry& out) {
  const Mesh& mesh = *scene_.mesh;
  const FaceRef face = scene_.locate(faceId);
  const uint32_t k = face.instance, f = face.meshFace, n = mesh.cornerCount(f);
  state_.assign(n, VertexState());
  window_.assign(n, Vec3());
  slot_.resize(n);
  instance_.assign(n, k);
  local_.resize(n);
  for (uint32_t i = 0; i < n; ++i) {
    slot_[i] = layout_.cornerSlots()[mesh.faceStart[f] + i];
    local_[i] = i;
    projectVertex(mvp_[k], layout_.slotPositions()[slot_[i]], viewport_, 1, state_[i], window_[i]);
  }
  out.width = viewport_.width * viewport_.scale;
  out.height = viewport_.height * viewport_.scale;
  assembler_.setVertices(
      VertexView{state_.data(), window_.data(), slot_.data(), instance_.data(), 0});
  assembler_.append(faceId, FaceCorners{local_.data(), 0}, n, out);
}

}  // namespace zrender::test
