#include "zrender/transform/FaceAssembler.hpp"

#include <algorithm>
#include <cmath>

#include "zrender/transform/Clipping.hpp"
#include "zrender/transform/Triangulation.hpp"

namespace zrender {

void FaceAssembler::beginFrame(int width, int height, const std::vector<Vec3>& slotPositions,
                               const std::vector<Mat4>& modelViewProjection) {
  width_ = width;
  height_ = height;
  slotPositions_ = &slotPositions;
  mvp_ = &modelViewProjection;
}

Vec4 FaceAssembler::clipOf(uint32_t vertex) const {
  size_t slot = 0, instance = 0;
  if (view_.slot) {
    slot = view_.slot[vertex];
    instance = view_.instance[vertex];
  } else {
    const size_t slots = slotPositions_->size();
    slot = vertex % slots;
    instance = view_.firstInstance + vertex / slots;
  }
  const Vec3& p = (*slotPositions_)[slot];
  return (*mvp_)[instance] * Vec4(p[0], p[1], p[2], 1.0);
}

float nearestCornerDepth(const Vec3* window, uint32_t count) {
  double lo = window[0][2];
  for (uint32_t i = 1; i < count; ++i) lo = std::min(lo, window[i][2]);
  float flo = static_cast<float>(std::max(lo, 0.0));
  if (double(flo) > lo) flo = nextFloatTowardZero(flo);
  return std::max(flo, 0.0f);
}

namespace {

// Sets the plane's clamp range to the corners' depths, widened to the enclosing floats.
void setDepthRange(DepthPlane& plane, const Vec3* window, uint32_t count) {
  double hi = window[0][2];
  for (uint32_t i = 1; i < count; ++i) hi = std::max(hi, window[i][2]);
  float fhi = static_cast<float>(std::min(hi, 1.0));
  if (double(fhi) < hi) fhi = nextFloatTowardOne(fhi);
  plane.loBits = int32_t(floatBits(nearestCornerDepth(window, count)));
  plane.hiBits = int32_t(floatBits(std::min(fhi, 1.0f)));
}

// The plane with `normal` through `point` (samples, samples, depth), clamped to the depth
// range of the polygon `window`; `ok` is false when the plane is vertical on screen. Inline in
// every caller: as a call, its result went through the stack, which measured slower on every
// algorithm's transform (docs/performance.md).
[[gnu::always_inline]] inline DepthPlane planeThrough(const Vec3& normal, const Vec3& point,
                                                      const Vec3* window, uint32_t count,
                                                      bool& ok) {
  DepthPlane plane;
  ok = normal[2] != 0.0 && std::isfinite(normal[2]);
  if (!ok) return plane;
  plane.a = -normal[0] / normal[2];
  plane.b = -normal[1] / normal[2];
  plane.c = point[2] - plane.a * point[0] - plane.b * point[1];
  setDepthRange(plane, window, count);
  return plane;
}

// Appends a face (its snapped corners and positively oriented pieces) to the frame.
void pushFace(uint32_t faceId, const DepthPlane& plane, bool frontFacing, const FixedPoint* corners,
              uint32_t cornerCount, const std::array<uint32_t, 3>* pieces, uint32_t pieceCount,
              FaceRowSpan rows, FrameGeometry& out) {
  ScreenFace face;
  face.id = faceId;
  face.firstVertex = uint32_t(out.vertices.size());
  face.vertexCount = uint16_t(cornerCount);
  face.firstTriangle = uint32_t(out.triangles.size());
  face.triangleCount = uint16_t(pieceCount);
  face.rows = rows;
  face.frontFacing = frontFacing;
  const uint32_t faceIndex = uint32_t(out.faces.size());
  // One by one: the range insert is a call, and faces have few corners.
  for (uint32_t i = 0; i < cornerCount; ++i) out.vertices.push_back(corners[i]);
  for (uint32_t i = 0; i < pieceCount; ++i) {
    const std::array<uint32_t, 3>& t = pieces[i];
    out.triangles.push_back(
        ScreenTriangle{{corners[t[0]], corners[t[1]], corners[t[2]]}, faceIndex, faceId, plane});
  }
  out.faces.push_back(face);
}

// Positive orientation (orient2d > 0) of a triangle's corners: y points down in window space,
// so a front face (counter-clockwise in NDC) has to be walked the other way round.
std::array<uint32_t, 3> orientedPiece(bool frontFacing) {
  return frontFacing ? std::array<uint32_t, 3>{0, 2, 1} : std::array<uint32_t, 3>{0, 1, 2};
}

}  // namespace

DepthPlane FaceAssembler::planeOf(const Vec3* window, uint32_t count, bool& ok) const {
  // Newell's normal of the window-space polygon (x, y in samples, z depth), through the
  // centroid: z = a x + b y + c. From the unsnapped positions.
  if (count == 3) {
    // A triangle's plane through its first corner: fewer operations than Newell's sum.
    const Vec3 p(window[0][0] * scale_, window[0][1] * scale_, window[0][2]);
    const Vec3 u(window[1][0] * scale_ - p[0], window[1][1] * scale_ - p[1], window[1][2] - p[2]);
    const Vec3 v(window[2][0] * scale_ - p[0], window[2][1] * scale_ - p[1], window[2][2] - p[2]);
    return planeThrough(u.cross(v), p, window, count, ok);
  }
  Vec3 normal(0, 0, 0), centre(0, 0, 0);
  for (uint32_t i = 0; i < count; ++i) {
    const Vec3& pw = window[i];
    const Vec3& qw = window[i + 1 == count ? 0 : i + 1];
    const Vec3 p(pw[0] * scale_, pw[1] * scale_, pw[2]), q(qw[0] * scale_, qw[1] * scale_, qw[2]);
    normal += Vec3((p[1] - q[1]) * (p[2] + q[2]), (p[2] - q[2]) * (p[0] + q[0]),
                   (p[0] - q[0]) * (p[1] + q[1]));
    centre += p;
  }
  centre *= 1.0 / count;
  return planeThrough(normal, centre, window, count, ok);
}

void FaceAssembler::appendFace(uint32_t faceId, FaceCorners corners, uint32_t n,
                               FrameGeometry& out) {
  TransformCounters& counters = out.counters;
  const uint64_t pieces = n >= 3 ? n - 2 : 1;  // counters are in triangles
  if (n < 3) {
    counters.degenerate += pieces;
    return;
  }
  uint32_t all = ~0u, any = 0;
  for (uint32_t i = 0; i < n; ++i) {
    all &= view_.state[corners[i]].code;
    any |= view_.state[corners[i]].code;
  }
  if (any & kNotFinite) {
    counters.degenerate += pieces;
    return;
  }
  if (all & 0x3F) {  // wholly beyond one plane of the view volume: covers nothing
    counters.clippedAway += pieces;
    return;
  }
  if (any & kNeedsClip) {
    appendClippedFace(faceId, corners, n, pieces, out);
    return;
  }
  if (n == 3) {
    appendTriangle(faceId, corners, out);
    return;
  }
  // Every corner inside near/far and the guard band, already snapped.
  snapped_.clear();
  for (uint32_t i = 0; i < n; ++i) {
    const FixedPoint& p = view_.state[corners[i]].snapped;
    if (snapped_.empty() || p != snapped_.back()) snapped_.push_back(p);
  }
  // Back faces are known from the snapped corners alone: decide before the plane's divisions.
  if (snapped_.size() == 3 && cull_) {
    const int64_t area = orient2d(snapped_[0], snapped_[1], snapped_[2]);
    if (area > 0) {  // clockwise in NDC (y points down here)
      counters.backfaceCulled += pieces;
      return;
    }
  }
  window_.resize(n);
  for (uint32_t i = 0; i < n; ++i) window_[i] = view_.window[corners[i]];
  bool ok = false;
  const DepthPlane plane = planeOf(window_.data(), n, ok);
  if (!ok) {
    counters.degenerate += pieces;
    return;
  }
  appendSnappedFace(faceId, plane, pieces, out);
}

void FaceAssembler::appendTriangle(uint32_t faceId, FaceCorners corners, FrameGeometry& out) {
  // The common case, kept short: a triangle inside near/far and the guard band. Same result
  // as appendSnappedFace() would give, without its scratch buffers.
  const FixedPoint& a = view_.state[corners[0]].snapped;
  const FixedPoint& b = view_.state[corners[1]].snapped;
  const FixedPoint& c = view_.state[corners[2]].snapped;
  const int64_t area = orient2d(a, b, c);
  FaceRowSpan rows;
  if (droppedBeforeDepths(a, b, c, area, out, rows)) return;
  appendTriangleDepths(faceId, corners, area < 0, rows, out);
}

void FaceAssembler::appendTriangleDepths(uint32_t faceId, FaceCorners corners, bool frontFacing,
                                         FaceRowSpan rows, FrameGeometry& out) {
  const FixedPoint points[3] = {view_.state[corners[0]].snapped, view_.state[corners[1]].snapped,
                                view_.state[corners[2]].snapped};
  const Vec3 window[3] = {view_.window[corners[0]], view_.window[corners[1]],
                          view_.window[corners[2]]};
  if (filter_ && filter_->hidden(points, nearestCornerDepth(window, 3), faceId)) return;
  bool ok = false;
  const DepthPlane plane = planeOf(window, 3, ok);
  if (!ok) {
    out.counters.degenerate += 1;
    return;
  }
  const std::array<uint32_t, 3> piece = orientedPiece(frontFacing);
  pushFace(faceId, plane, frontFacing, points, 3, &piece, 1, rows, out);
}

void FaceAssembler::appendClippedFace(uint32_t faceId, FaceCorners corners, uint32_t n,
                                      uint64_t pieces, FrameGeometry& out) {
  TransformCounters& counters = out.counters;
  faceClip_.resize(n);
  uint32_t any = 0;
  for (uint32_t i = 0; i < n; ++i) {
    faceClip_[i] = clipOf(corners[i]);
    any |= view_.state[corners[i]].code;
  }
  const Vec4* poly = faceClip_.data();
  uint32_t count = n;
  if (any & (kNear | kFar)) {
    clipped_.resize(clipNearFarCapacity(n));
    clipScratch_.resize(clipNearFarCapacity(n));
    count = uint32_t(clipNearFar(poly, n, clipped_.data(), clipScratch_.data()));
    if (count == 0) {
      counters.clippedAway += pieces;
      return;
    }
    poly = clipped_.data();
  }
  window_.resize(count);
  for (uint32_t i = 0; i < count; ++i) window_[i] = clipToWindow(poly[i], width_, height_);

  // Keep snapped coordinates in range however far outside the image the face reaches.
  const double guard = kGuardBand / scale_;
  const Vec3* win = window_.data();
  bool outside = false;
  for (uint32_t i = 0; i < count; ++i)
    outside |= std::abs(win[i][0]) > guard || std::abs(win[i][1]) > guard;
  if (outside) {
    guarded_.resize(clipGuardBandCapacity(count));
    guardScratch_.resize(clipGuardBandCapacity(count));
    count = uint32_t(clipGuardBand(win, count, guard, guarded_.data(), guardScratch_.data()));
    if (count == 0) {
      counters.clippedAway += pieces;
      return;
    }
    win = guarded_.data();
  }
  // The plane from the corners within the guard band: those of a face reaching 1e155 units
  // would overflow its normal (their cross product) and lose a face that covers the image.
  bool ok = false;
  const DepthPlane plane = planeOf(win, count, ok);
  if (!ok) {
    counters.degenerate += pieces;
    return;
  }
  snapped_.clear();
  for (uint32_t i = 0; i < count; ++i) {
    const FixedPoint p{snapToSubpixel(win[i][0]) * scale_, snapToSubpixel(win[i][1]) * scale_};
    if (snapped_.empty() || p != snapped_.back()) snapped_.push_back(p);
  }
  appendSnappedFace(faceId, plane, pieces, out);
}

void FaceAssembler::appendSnappedFace(uint32_t faceId, const DepthPlane& plane, uint64_t pieces,
                                      FrameGeometry& out) {
  TransformCounters& counters = out.counters;
  while (snapped_.size() > 1 && snapped_.back() == snapped_.front()) snapped_.pop_back();
  // More corners than ScreenFace counts (an OBJ face has at most 4096 before clipping, which
  // adds fewer than this allows): not drawn, as no algorithm could draw it the same way.
  if (snapped_.size() < 3 || snapped_.size() > kMaxScreenFaceCorners) {
    counters.degenerate += pieces;
    return;
  }
  __int128 area = 0;
  for (size_t i = 0; i < snapped_.size(); ++i) {
    const FixedPoint& a = snapped_[i];
    const FixedPoint& b = snapped_[i + 1 == snapped_.size() ? 0 : i + 1];
    area += __int128(int64_t(a.x) * b.y - int64_t(b.x) * a.y);
  }
  if (area == 0) {
    counters.degenerate += pieces;
    return;
  }
  // y points down in window space, so counter-clockwise in NDC is a negative area here.
  const bool frontFacing = area < 0;
  if (cull_ && !frontFacing) {
    counters.backfaceCulled += pieces;
    return;
  }
  pieces_.clear();
  if (snapped_.size() == 3) {
    pieces_.push_back(orientedPiece(frontFacing));
  } else if (!triangulatePolygon(snapped_.data(), uint32_t(snapped_.size()), pieces_, ring_) ||
             pieces_.empty()) {
    counters.degenerate += pieces;
    return;
  }

  int32_t minY = snapped_[0].y, maxY = snapped_[0].y;
  for (const FixedPoint& p : snapped_) {
    minY = std::min(minY, p.y);
    maxY = std::max(maxY, p.y);
  }
  pushFace(faceId, plane, frontFacing, snapped_.data(), uint32_t(snapped_.size()), pieces_.data(),
           uint32_t(pieces_.size()), faceRowSpan(minY, maxY, out.height), out);
}

}  // namespace zrender
