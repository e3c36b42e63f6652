#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "zrender/raster/FrameGeometry.hpp"
#include "zrender/scene/Transforms.hpp"
#include "zrender/transform/GeometrySource.hpp"
#include "zrender/transform/VertexProjection.hpp"

namespace zrender {

// The vertices the faces being assembled refer to, as the transform computed them in this
// frame: one instance's, numbered by slot (`slot` and `instance` null; vertex v is slot
// v % slots of instance firstInstance + v / slots), or one batch's, under local numbers each
// with its slot and instance.
struct VertexView {
  const VertexState* state = nullptr;
  const Vec3* window = nullptr;
  const uint32_t* slot = nullptr;
  const uint32_t* instance = nullptr;
  uint32_t firstInstance = 0;
};

// The corners of one face as vertex numbers of a VertexView: base + slots[i].
struct FaceCorners {
  const uint32_t* slots;
  uint32_t base;
  uint32_t operator[](uint32_t i) const { return base + slots[i]; }
};

// The least corner depth of a face as DepthPlane::minDepth() holds it: the greatest float not
// above the least of `window[i][2]`, clamped to [0, 1].
float nearestCornerDepth(const Vec3* window, uint32_t count);

// One face from its transformed vertices to the frame's geometry (docs/design.md, The
// transform): near/far clipping in clip space, the 2D guard band, snapping, back-face culling,
// the depth plane and the window-space triangulation of polygons. A triangle face that needs
// no clipping and covers no sample centre is left out (it could not change any buffer), and so
// is one a TriangleFilter proves hidden.
class FaceAssembler {
 public:
  // sampleScale: 1, or 2 for MSAA 4 (the four samples of a pixel are a 2 x 2 grid of samples).
  FaceAssembler(int sampleScale, bool cull) : scale_(sampleScale), cull_(cull) {}

  // The frame: the image in pixels, and what recomputes clip coordinates for the faces that
  // need clipping (VertexState keeps only the outcode and the window position): the model
  // positions by slot and the model-view-projection of each instance. Both must outlive the
  // frame.
  void beginFrame(int width, int height, const std::vector<Vec3>& slotPositions,
                  const std::vector<Mat4>& modelViewProjection);
  // The vertices the next faces refer to, and what may drop them early.
  void setVertices(const VertexView& view) { view_ = view; }
  void setFilter(TriangleFilter* filter, HiddenTiles hidden) {
    filter_ = filter && filter->asksFaces() ? filter : nullptr;
    hiddenTiles_ = hidden;
  }

  // Appends face `faceId` of `count` corners. Its common case is inline: a triangle whose
  // corners all lie inside the view volume's planes and the guard band (most faces).
  void append(uint32_t faceId, FaceCorners corners, uint32_t count, FrameGeometry& out) {
    const VertexState* state = view_.state;
    if (count == 3 &&
        (state[corners[0]].code | state[corners[1]].code | state[corners[2]].code) == 0) {
      const FixedPoint& a = state[corners[0]].snapped;
      const FixedPoint& b = state[corners[1]].snapped;
      const FixedPoint& c = state[corners[2]].snapped;
      const int64_t area = orient2d(a, b, c);
      FaceRowSpan rows;
      if (!droppedBeforeDepths(a, b, c, area, out, rows))
        appendTriangleDepths(faceId, corners, area < 0, rows, out);
      return;
    }
    appendFace(faceId, corners, count, out);
  }

 private:
  // The checks that need only the snapped corners (degenerate, back face: counted; no sample
  // centre covered: not counted, as no set-up ever counted it; hidden tiles: counted); true
  // when the face goes no further. Otherwise `rows` are the sample rows it spans.
  bool droppedBeforeDepths(const FixedPoint& a, const FixedPoint& b, const FixedPoint& c,
                           int64_t area, FrameGeometry& out, FaceRowSpan& rows) const {
    TransformCounters& counters = out.counters;
    if (area == 0) {
      counters.degenerate += 1;
      return true;
    }
    // y points down in window space, so counter-clockwise in NDC is a negative area here.
    if (cull_ && area > 0) {
      counters.backfaceCulled += 1;
      return true;
    }
    // A face that covers no sample centre would be set up and stored to draw nothing.
    const SampleRect r = sampleBounds(a, b, c, out.width, out.height);
    if (r.empty()) return true;
    rows = FaceRowSpan{uint16_t(r.minY), uint16_t(r.maxY)};
    // Where the instance's nearest depth is hidden, which needs no depth loaded: enough for a
    // face of an instance wholly behind what is drawn there.
    if (!hiddenTiles_.marked) return false;
    const int shift = hiddenTiles_.tileShift;
    const int x0 = r.minX >> shift, x1 = r.maxX >> shift, y0 = r.minY >> shift,
              y1 = r.maxY >> shift;
    if (x1 - x0 > 1 || y1 - y0 > 1) return false;
    const uint8_t* r0 = hiddenTiles_.marked + size_t(y0) * size_t(hiddenTiles_.tilesX);
    const uint8_t* r1 = hiddenTiles_.marked + size_t(y1) * size_t(hiddenTiles_.tilesX);
    if (!(r0[x0] & r0[x1] & r1[x0] & r1[x1])) return false;
    ++counters.filtered;
    return true;
  }
  void appendFace(uint32_t faceId, FaceCorners corners, uint32_t count, FrameGeometry& out);
  void appendTriangle(uint32_t faceId, FaceCorners corners, FrameGeometry& out);
  void appendTriangleDepths(uint32_t faceId, FaceCorners corners, bool frontFacing,
                            FaceRowSpan rows, FrameGeometry& out);
  void appendClippedFace(uint32_t faceId, FaceCorners corners, uint32_t count, uint64_t pieces,
                         FrameGeometry& out);
  void appendSnappedFace(uint32_t faceId, const DepthPlane& plane, uint64_t pieces,
                         FrameGeometry& out);
  DepthPlane planeOf(const Vec3* window, uint32_t count, bool& ok) const;
  Vec4 clipOf(uint32_t vertex) const;

  int width_ = 0, height_ = 0;  // pixels
  int scale_;
  bool cull_;
  const std::vector<Vec3>* slotPositions_ = nullptr;
  const std::vector<Mat4>* mvp_ = nullptr;
  VertexView view_;
  TriangleFilter* filter_ = nullptr;
  HiddenTiles hiddenTiles_;
  // Scratch buffers reused face after face.
  std::vector<Vec4> faceClip_, clipped_, clipScratch_;
  std::vector<Vec3> window_, guarded_, guardScratch_;
  std::vector<FixedPoint> snapped_;
  std::vector<std::array<uint32_t, 3>> pieces_;
  std::vector<uint32_t> ring_;
};

}  // namespace zrender
