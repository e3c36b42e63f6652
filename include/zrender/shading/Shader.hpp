#pragma once

#include <vector>

#include <opencv2/core.hpp>

#include "zrender/raster/FrameBuffer.hpp"
#include "zrender/raster/FrameGeometry.hpp"
#include "zrender/scene/Camera.hpp"
#include "zrender/scene/Scene.hpp"
#include "zrender/scene/ShadingMode.hpp"

namespace zrender {

// Deferred shading (SPEC §6): turns the visibility buffer into colors. A sample's color depends
// only on its face id, its position and the scene, never on the algorithm that found it, so
// identical visibility buffers give identical images. Attributes are interpolated
// perspective-correctly by intersecting the sample's view ray with the face in view space.
class Shader {
 public:
  Shader(const Scene& scene, ShadingMode mode);

  // Fills `color` (CV_8UC3, BGR, pixels) from `fb` (samples; sampleScale 2 = MSAA 4, whose
  // pixel is the rounded mean of its four samples' colors, background included; in id mode,
  // the color of its nearest sample, as idImage()).
  void shade(const FrameBuffer& fb, const Camera& camera, int sampleScale, cv::Mat& color);

  // The same in steps, so that rows are colored while their keys are still in cache: begin()
  // sizes `color` and sets the frame up (`geometry`, when given, holds every face that may be
  // in `fb` by the time its rows are shaded: only those faces' colors are computed);
  // rowsFinal(n) says that sample rows [0, n) of `fb` hold their final keys and colors the
  // pixel rows they complete (depth mode, which stretches over the whole frame's depths,
  // waits); finish() colors the rest. `fb` and `color` must stay alive and unresized until
  // finish().
  void begin(const FrameBuffer& fb, const Camera& camera, int sampleScale, cv::Mat& color,
             const FrameGeometry* geometry = nullptr);
  void rowsFinal(int sampleRows);
  void finish();

 private:
  struct FaceCache {
    uint32_t stamp = 0;  // frame in which the entry was computed
    uint32_t data = 0;   // packed BGR color, or index into faceShade_ for per-sample modes
  };
  struct FaceShade {  // view-space data of one face for per-sample interpolation
    uint32_t first;   // into cornerPos_/cornerNormal_/cornerUv_
    uint32_t count;
    bool flip;       // back-facing: light the other side
    cv::Vec3f base;  // material diffuse color, RGB 0..1
  };

  uint32_t faceColor(uint32_t faceId);  // through cache_, for faces met pixel by pixel
  uint32_t uncachedFaceColor(uint32_t faceId) const;
  uint32_t normalColor(const Mat4& modelView, uint32_t local) const;  // packed, mesh face
  uint32_t sampleColor(DepthKey key, int x, int y);                   // 0x00RRGGBB; x, y in samples
  void shadePixelRows(int endRow);  // rows [shadedRows_, endRow) of the image
  void prepareTable();  // decides on colorTable_ and brings it up to date with the geometry
  uint32_t faceShadeIndex(uint32_t faceId);
  cv::Vec3b shadeSample(uint32_t faceId, const Vec3& rayDir);
  cv::Vec3f sampleTexture(const cv::Vec2d& uv) const;

  const Scene& scene_;
  ShadingMode mode_;
  std::vector<Vec3> faceNormals_;    // model space, per local face (Newell, unit or zero)
  std::vector<Vec3> smoothNormals_;  // model space, per position, when the model has no vn
  bool perSample_ = false;

  // Per-frame state.
  const FrameBuffer* fb_ = nullptr;
  cv::Mat* color_ = nullptr;
  int scale_ = 1;
  int shadedRows_ = 0;  // pixel rows colored so far
  uint32_t background_ = 0;
  const FrameGeometry* geometry_ = nullptr;
  bool perFace_ = false;  // one sample per pixel, one color per face
  // Every instance's model-view rotation (3 x 3) equals the first one's, as for grids.
  bool sharedRotation_ = false;
  // On: colorTable_ by face id; MeshFaces: meshColors_ by mesh face (normal mode, shared
  // rotation); Off: computed on first sight.
  enum class TableState { Undecided, On, MeshFaces, Off } tableState_ = TableState::Undecided;
  size_t tableFaces_ = 0;  // geometry faces whose colors colorTable_ holds
  float depthLo_ = 0.0f;   // depth mode: the frame's depth range
  double depthRange_ = 1.0;
  double rayScaleX_ = 0.0, rayScaleY_ = 0.0, rayOriginX_ = 0.0, rayOriginY_ = 0.0;
  uint32_t frame_ = 0;
  std::vector<FaceCache> cache_;
  std::vector<uint32_t> colorTable_;  // [0] background, [id + 1] face color (one color per face)
  std::vector<uint32_t> meshColors_;  // per mesh face: its normal color (TableState::MeshFaces)
  std::vector<FaceShade> faceShade_;
  std::vector<Vec3> cornerPos_, cornerNormal_;
  std::vector<cv::Vec2d> cornerUv_;
  std::vector<Mat4> modelView_;  // per instance
};

// A fixed pseudo-random color per face id (SPEC §6 `random`), packed as 0x00RRGGBB.
uint32_t randomFaceColor(uint32_t faceId);

}  // namespace zrender
