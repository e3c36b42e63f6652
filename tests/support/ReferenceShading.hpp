#pragma once

#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "zrender/raster/FrameBuffer.hpp"
#include "zrender/scene/Camera.hpp"
#include "zrender/scene/Scene.hpp"
#include "zrender/scene/ShadingMode.hpp"

namespace zrender::test {

// The shader zrender had before its float, vector one (docs/design.md, Faces, ids and
// shading): kept as the reference that the fast shader must stay within 1 (of 255) of.

// The color of a sample in the modes that interpolate attributes over a face: `phong`,
// `texture`, and `normal` for a model with vertex normals, all in double. Attributes are
// interpolated perspective-correctly by intersecting the sample's view ray with the face in
// view space (Moeller-Trumbore; a polygon: the fan triangle from its first corner that
// contains the hit, else the one it misses least).
class ReferenceSurfaceShading {
 public:
  ReferenceSurfaceShading(const Scene& scene, ShadingMode mode);

  // Starts a frame: `modelView` per instance (kept by reference until the next begin()), for a
  // buffer of `widthSamples` x `heightSamples` seen through `camera`.
  void begin(const std::vector<Mat4>& modelView, const Camera& camera, int widthSamples,
             int heightSamples);

  // Face `faceId`'s packed color (0x00RRGGBB) at the centre of sample (x, y).
  uint32_t color(uint32_t faceId, int x, int y);

 private:
  struct FaceShade {  // view-space data of one face for per-sample interpolation
    uint32_t first;   // into cornerPos_/cornerNormal_/cornerUv_
    uint32_t count;
    bool flip;                         // back-facing: light the other side
    cv::Vec3f base;                    // material diffuse color, RGB 0..1
    const cv::Mat* texture = nullptr;  // sampled in place of base when there is one
  };
  uint32_t faceShadeIndex(uint32_t faceId);
  cv::Vec3f sampleTexture(const cv::Mat& t, const cv::Vec2d& uv) const;

  const Scene& scene_;
  ShadingMode mode_;
  std::vector<Vec3> faceNormals_;    // model space, per mesh face (Newell, unit or zero)
  std::vector<Vec3> smoothNormals_;  // model space, per position, when the model has no vn

  // Per frame.
  const std::vector<Mat4>* modelView_ = nullptr;
  double rayScaleX_ = 0.0, rayScaleY_ = 0.0, rayOriginX_ = 0.0, rayOriginY_ = 0.0;
  struct Cached {
    uint32_t stamp = 0;  // frame in which the entry was computed
    uint32_t index = 0;  // into faceShade_
  };
  uint32_t frame_ = 0;
  std::vector<Cached> cache_;
  std::vector<FaceShade> faceShade_;
  std::vector<Vec3> cornerPos_, cornerNormal_;
  std::vector<cv::Vec2d> cornerUv_;
};

// The image (CV_8UC3, BGR, pixels) that the reference shader makes of `fb` (samples;
// `sampleScale` 2 for MSAA 4) of `scene` seen through `camera`, as Shader::shade does: the
// surface modes by ReferenceSurfaceShading, the others by FaceColors and the depth formula;
// with MSAA the rounded mean of a pixel's four samples, except in id mode (its nearest).
cv::Mat referenceImage(const Scene& scene, const Camera& camera, const FrameBuffer& fb,
                       int sampleScale);

}  // namespace zrender::test
