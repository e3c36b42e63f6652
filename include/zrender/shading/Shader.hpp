#pragma once

#include <memory>
#include <optional>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "zrender/base/Threads.hpp"
#include "zrender/raster/FrameBuffer.hpp"
#include "zrender/raster/FrameGeometry.hpp"
#include "zrender/scene/Camera.hpp"
#include "zrender/scene/Scene.hpp"
#include "zrender/scene/ShadingMode.hpp"
#include "zrender/shading/FaceColors.hpp"
#include "zrender/shading/PixelRows.hpp"
#include "zrender/shading/SurfaceSetup.hpp"

namespace zrender {

// One frame's shading state (Shader::begin() sets it up; the other calls of Shader take it):
// the buffer being shaded and the image being written, which must stay alive and unresized
// until Shader::finish(), and what has been prepared and colored so far. Kept from frame to
// frame by its owner, so that its arrays are reused.
struct ShadingFrame {
  const FrameBuffer* fb = nullptr;
  cv::Mat* color = nullptr;
  const Threads* threads = nullptr;  // null or one: the calling thread alone
  int scale = 1;                     // samples per pixel along an axis (2: MSAA 4)
  uint32_t background = 0;           // 0x00RRGGBB
  FaceParts faces;                   // the frame's faces, when gathered
  bool perFace = false;              // one sample per pixel, one color per face
  FaceColors::Lookup lookup = FaceColors::Lookup::OnSight;  // after FaceColors::prepare()
  float depthLo = 0.0f;  // depth mode: the frame's range of window depths
  double depthRange = 1.0;
  std::vector<Mat4> modelView;      // per instance
  std::vector<uint32_t> rowColors;  // scratch: two sample rows of packed colors
  int shadedRows = 0;               // one thread: pixel rows [0, shadedRows) are colored
  // Several threads: whether the faces are prepared (rowsDone() colors rows then), and which
  // pixel rows are colored.
  bool earlyShading = false;
  std::vector<uint8_t> rowDone;

  bool parallel() const { return threads != nullptr && threads->parallel(); }
};

// Deferred shading (docs/design.md, Faces, ids and shading): turns the visibility buffer into
// colors. A sample's color depends only on its face id, its position and the scene, never on
// the algorithm that found it, so identical visibility buffers give identical images. Colors
// come from FaceColors (one per face) or, for runs of a face's samples, SurfaceSetup and
// SurfaceKernel; with MSAA 4 a pixel is the rounded mean of its four samples' colors,
// background included, except in id mode, where it is its nearest sample's.
//
// A frame is shaded by begin(), then any rowsDone() the algorithm reports (so that rows are
// colored while their keys are still in cache), then finish(), which colors the rest; or by
// shade(), which is begin() and finish().
class Shader {
 public:
  Shader(const Scene& scene, ShadingMode mode);

  // Fills `color` (8-bit BGR, pixels) from `fb` (samples; sampleScale 2 = MSAA 4) on the
  // calling thread.
  void shade(const FrameBuffer& fb, const Camera& camera, int sampleScale, cv::Mat& color);

  // Sizes `color` and sets `frame` up for `fb`, seen through `camera`. `geometry`, when given,
  // holds every face that may be in `fb` by the time its rows are shaded (only those faces'
  // colors are computed). `threads`: those finish() and the prepared faces may use.
  void begin(ShadingFrame& frame, const FrameBuffer& fb, const Camera& camera, int sampleScale,
             cv::Mat& color, const FrameGeometry* geometry, const Threads* threads = nullptr);
  // With several threads, once the parts `faces` hold every face of the frame (empty: not
  // gathered; they are found otherwise, all the scene's or those in the buffer): prepares
  // their colors or surfaces, where that needs no final buffer (not in depth mode, nor for
  // surfaces of a geometry too big to set up whole), so that rowsDone() colors rows from any
  // thread.
  void facesGathered(ShadingFrame& frame, const FaceParts& faces);
  // Sample rows [first, end) of the buffer hold their final keys: colors the pixel rows they
  // complete, if it can yet. With one thread, the calls come top to bottom, each `first` the
  // previous `end` (depth mode, which stretches over the whole frame's depths, waits for
  // finish()). With several, from any thread at once, for rows that never overlap, after
  // facesGathered().
  void rowsDone(ShadingFrame& frame, int first, int end);
  // Colors the rows left, shared out among the frame's threads.
  void finish(ShadingFrame& frame);

 private:
  // The packed color (0x00RRGGBB) of a sample, in the modes without a surface. `shared`: from
  // one of several threads at once, which then write nothing but the image (every face in the
  // buffer is prepared before), here and in the functions below.
  uint32_t sampleColor(const ShadingFrame& frame, DepthKey key, bool shared);
  uint32_t sharedFaceColor(const ShadingFrame& frame, uint32_t id) const;
  // The packed colors of sample row y, into out[0, buffer width).
  void colorSampleRow(const ShadingFrame& frame, int y, uint32_t* out, bool shared);
  // One thread: rows [frame.shadedRows, endRow) of the image.
  void shadePixelRows(ShadingFrame& frame, int endRow);
  // Colors pixel rows [firstRow, endRow), with `rowColors` as scratch.
  void paintRows(const ShadingFrame& frame, int firstRow, int endRow,
                 std::vector<uint32_t>& rowColors, bool shared);
  // Prepares the faces' colors or surfaces for shared use; false when that needs the final
  // buffer (prepareFaces(frame, true) then does).
  bool prepareFaces(ShadingFrame& frame, bool bufferFinal);
  // Sets frame.depthLo and frame.depthRange from the buffer's depths.
  void findDepthRange(ShadingFrame& frame) const;

  const Scene& scene_;
  ShadingMode mode_;
  std::optional<FaceColors> faceColors_;  // one color per face
  std::optional<SurfaceSetup> surface_;   // attributes interpolated per sample
  SurfaceRowFunction surfaceRow_;
  SurfaceBgrRowFunction surfaceBgrRow_;  // none: surfaceRow_, then packBgr_
  PackBgrFunction packBgr_;
};

}  // namespace zrender
