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

// Deferred shading (docs/design.md, Faces, ids and shading): turns the visibility buffer into
// colors. A sample's color depends only on its face id, its position and the scene, never on
// the algorithm that found it, so identical visibility buffers give identical images. Colors
// come from FaceColors (one per face) or, for runs of a face's samples, SurfaceSetup and
// SurfaceKernel; with MSAA 4 a pixel is
// the rounded mean of its four samples' colors, background included, except in id mode, where
// it is its nearest sample's.
class Shader {
 public:
  Shader(const Scene& scene, ShadingMode mode);

  // Fills `color` (8-bit BGR, pixels) from `fb` (samples; sampleScale 2 = MSAA 4, whose
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
  // finish() with the rows shared out among `threads` (with one thread, finish() itself).
  void finish(const Threads& threads);
  // With several threads, once the geometry holds every face of the frame: prepares their
  // colors or surfaces on `threads`, where that needs no final buffer (not in depth mode, nor
  // for surfaces of a geometry too big to set up whole). Then rowsReady(first, end) colors the
  // pixel rows that sample rows [first, end) complete, from any thread (disjoint rows at once);
  // finish(threads) colors the rows left.
  void prepareRows(const Threads& threads);
  // The frame's faces are those of the parts `faces` rather than of the geometry given to
  // begin(); empty: they are not gathered, and are found otherwise (all the scene's, or those
  // in the buffer).
  void useFaces(const FaceParts& faces);
  void rowsReady(int first, int end);

 private:
  // The packed color (0x00RRGGBB) of a sample, in the modes without a surface. `shared`: from
  // one of several threads at once, which then write nothing but the image (every face in the
  // buffer is prepared before), here and in the functions below.
  uint32_t sampleColor(DepthKey key, bool shared);
  uint32_t sharedFaceColor(uint32_t id) const;
  // The packed colors of sample row y, into out[0, buffer width).
  void colorSampleRow(int y, uint32_t* out, bool shared);
  void shadePixelRows(int endRow);  // rows [shadedRows_, endRow) of the image
  // Colors pixel rows [firstRow, endRow), with `rowColors` as scratch.
  void paintRows(int firstRow, int endRow, std::vector<uint32_t>& rowColors, bool shared);
  // Prepares the faces' colors or surfaces for shared use; false when that needs the final
  // buffer (prepareFaces(threads, true) then does).
  bool prepareFaces(const Threads& threads, bool bufferFinal);
  // The least and greatest depth of samples [begin, end) of the buffer (lo 1, hi 0: none).
  void findDepthRange(size_t begin, size_t end, float& lo, float& hi) const;

  const Scene& scene_;
  ShadingMode mode_;
  std::optional<FaceColors> faceColors_;  // one color per face
  std::optional<SurfaceSetup> surface_;   // attributes interpolated per sample
  SurfaceRowFunction surfaceRow_;
  SurfaceBgrRowFunction surfaceBgrRow_;  // none: surfaceRow_, then packBgr_
  PackBgrFunction packBgr_;

  // Per frame.
  const FrameBuffer* fb_ = nullptr;
  cv::Mat* color_ = nullptr;
  int scale_ = 1;
  int shadedRows_ = 0;  // pixel rows colored so far
  uint32_t background_ = 0;
  FaceParts faces_;       // the frame's faces, when given
  bool perFace_ = false;  // one sample per pixel, one color per face
  FaceColors::Lookup lookup_ = FaceColors::Lookup::OnSight;  // after FaceColors::prepare()
  float depthLo_ = 0.0f;                                     // depth mode: the frame's depth range
  double depthRange_ = 1.0;
  std::vector<Mat4> modelView_;      // per instance
  std::vector<uint32_t> rowColors_;  // two sample rows of packed colors
  // With several threads: whether faces are prepared (rowsReady), and the pixel rows colored.
  bool earlyShading_ = false;
  std::vector<uint8_t> rowDone_;
};

}  // namespace zrender
