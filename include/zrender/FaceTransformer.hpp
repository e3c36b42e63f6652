#pragma once

#include <array>
#include <vector>

#include "zrender/Camera.hpp"
#include "zrender/FrameGeometry.hpp"
#include "zrender/Scene.hpp"

namespace zrender {

// Vertices to window coordinates, near/far clipping, snapping, back-face culling and window
// space triangulation: the transform stage of SPEC §4–5, shared by every algorithm.
class FaceTransformer {
 public:
  // sampleScale: 1, or 2 for MSAA 4 (the four samples of a pixel are a 2 x 2 grid of samples).
  FaceTransformer(const Scene& scene, const Camera& camera, int sampleScale, bool cull);

  // Every face of every instance, in face id order.
  void transformAll(FrameGeometry& out);

  // One face (global id); its vertices are transformed on first use in this frame. For
  // algorithms that skip most of the model (the octree).
  void transformFace(uint32_t faceId, FrameGeometry& out);

  const Mat4& modelViewProjection(uint32_t instance) const { return mvp_[instance]; }
  int sampleScale() const { return scale_; }

 private:
  void appendFace(uint32_t faceId, const Vec4* clip, uint32_t count, FrameGeometry& out);
  const Vec4& lazyClipVertex(uint32_t instance, int32_t vertex);

  const Scene& scene_;
  const Camera& camera_;
  int scale_;
  bool cull_;
  std::vector<Mat4> mvp_;           // per instance, model to clip space
  std::vector<Vec4> clip_;          // clip-space vertex (instance-major) when transformed
  std::vector<uint8_t> clipReady_;  // lazy mode: vertex transformed this frame
  // Scratch buffers reused face after face.
  std::vector<Vec4> faceClip_, clipped_, clipScratch_;
  std::vector<Vec3> window_, guarded_, guardScratch_;
  std::vector<FixedPoint> snapped_;
  std::vector<std::array<uint32_t, 3>> pieces_;
  std::vector<uint32_t> ring_;
};

}  // namespace zrender
