#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "zrender/base/Prefetch.hpp"
#include "zrender/base/Threads.hpp"
#include "zrender/base/UninitializedAllocator.hpp"
#include "zrender/raster/FrameBuffer.hpp"
#include "zrender/raster/FrameGeometry.hpp"
#include "zrender/scene/Camera.hpp"
#include "zrender/scene/Scene.hpp"
#include "zrender/scene/ShadingMode.hpp"
#include "zrender/shading/SurfaceKernel.hpp"

namespace zrender {

// The per-face part of the modes that interpolate attributes over a face (`normal` with vertex
// normals, `phong`, `texture`): once per frame for each face that shows, in double, the planes
// and corner attributes that SurfaceKernel's per-sample loops read in float. Only faces in the
// buffer are set up, on first sight, so hidden faces cost nothing (docs/design.md, Shading).
class SurfaceSetup {
 public:
  SurfaceSetup(const Scene& scene, ShadingMode mode);

  // Starts a frame: `modelView` per instance (kept by reference until the next begin()), for a
  // buffer of `widthSamples` x `heightSamples` seen through `camera`.
  void begin(const std::vector<Mat4>& modelView, const Camera& camera, int widthSamples,
             int heightSamples);
  const SurfaceFrame& frame() const { return frame_; }

  // The surface of face `faceId`, set up on the first call for it in the frame; valid until
  // the next call.
  const FaceSurface& surface(uint32_t faceId) {
    Cached& entry = cache_[faceId];
    if (entry.stamp != stamp_) {
      entry.stamp = stamp_;
      entry.index = setUp(faceId);
    }
    return records_[entry.index].face;
  }
  // The fans of a face that surface() returned, until the next call of surface().
  const SurfaceFan* fans(const FaceSurface& face) const {
    if (face.fanCount != 1) return fans_.data() + face.firstFan;
    return &reinterpret_cast<const SurfaceRecord*>(reinterpret_cast<const char*>(&face) -
                                                   offsetof(SurfaceRecord, face))
                ->fan;
  }

  // Sets up every face of `faces` (the frame's faces, which hold those in the buffer) in a
  // batch, on `threads` when given, each face's data fetched into cache a few faces ahead,
  // instead of one cache miss after another as rows meet the faces; only when the faces are
  // few for the buffer's `samples` (a grid's many hidden faces are set up on first sight).
  // Once per frame; true when the batch was set up.
  bool setUpFaces(const FaceParts& faces, size_t samples, const Threads* threads = nullptr);
  // Fetches into cache, ahead of the row that meets them first, what the batch's faces whose
  // first row is `y` are looked up by: their cache entries and records (which lie side by
  // side, setUpFaces()). A hint: it changes no color, and does nothing without a batch.
  void prefetchRow(int y) const {
    if (!byRows_ || y <= 0 || y >= height_) return;
    const uint32_t begin = rowStart_[size_t(y) - 1], end = rowStart_[size_t(y)];
    if (begin == end) return;
    for (uint32_t i = begin; i < end; ++i) prefetchLine(&cache_[rowOrder_[i]]);
    prefetchRecords(begin, end);
  }
  // The same for every face of the scene, for a frame whose geometry is not at hand (the
  // octree's bands pull theirs apart): only when they are few for the buffer's `samples`.
  bool setUpAll(size_t samples);
  // Sets up every face in `fb`, so that several threads can then color its rows at once:
  // setUpFaces() when `faces` are given and that sets them up, else the faces found in the
  // buffer (scanned by `threads`).
  void setUpVisible(const FrameBuffer& fb, const FaceParts& faces, const Threads& threads);

 private:
  // A face's surface, and its fan when it is a triangle (most faces): side by side, so that the
  // rows' first look at a face fetches adjacent cache lines instead of one line after another
  // from two arrays (docs/design.md, Shading).
  struct SurfaceRecord {
    SurfaceFan fan;
    // Left unconstructed by records_.resize(), written in full by setUpInto(): a batch's
    // records, initialized first, would be written twice (a frame's records are megabytes).
    union {
      FaceSurface face;
    };
    SurfaceRecord() {}
  };
  static_assert(sizeof(SurfaceRecord) == 192, "a record is three cache lines");
  struct Scratch {
    std::vector<Vec3> position, normal;  // one face's corners, view space
  };
  static uint32_t fanCount(uint32_t corners) { return std::max<uint32_t>(corners, 3) - 2; }
  // Sets face `faceId` up in a new record; returns its index.
  uint32_t setUp(uint32_t faceId);
  // Sets the face at `ref` up in `record`, a polygon's fans in polygonFans[0, fanCount), which
  // are fans_ from `firstFan` on. Writes nothing else: threads may set up faces side by side.
  void setUpInto(const FaceRef& ref, SurfaceRecord& record, SurfaceFan* polygonFans,
                 uint32_t firstFan, Scratch& scratch) const;
  // setUpInto() for four faces of a mesh of triangles at once (SurfaceSetupAvx2.cpp), in
  // AVX2's four doubles: its operations lane by lane, in the same order, so the same bits
  // (tested). Call only when cpuHasAvx2() and triangles_.
  void setUpFourTriangles(const uint32_t faceIds[4], SurfaceRecord* const records[4],
                          const uint32_t firstFans[4]) const;
  // Fetches into cache the lines of the batch's records [from, to) (rowOrder_'s order).
  void prefetchRecords(size_t from, size_t to) const {
    const char* first = reinterpret_cast<const char*>(records_.data() + batchFirstRecord_ + from);
    const char* last = reinterpret_cast<const char*>(records_.data() + batchFirstRecord_ + to);
    for (const char* p = first; p < last; p += 64) prefetchLine(p);
  }
  // What a face's surface takes from its instance and material: base color and texture.
  FaceSurface faceFields(const FaceRef& ref) const;
  // Sets face.originX and originY from the first corner p0 (view space).
  void placeOrigin(FaceSurface& face, const Vec3& p0) const;

  // What setting a face up reads, gathered per mesh face at construction: a face met for the
  // first time is far in memory from the last one, and its corners' positions, normals and
  // texture coordinates would be as many cache misses in the mesh's own arrays.
  struct CornerData {
    Vec3 position;     // model space
    cv::Vec3f normal;  // model space: the vertex normal, the smooth one, or the face's
    cv::Vec2f uv;      // (0, 0) unless every corner of the face has one
  };
  struct FaceData {
    cv::Vec3f geometric;  // the face's own normal (Newell), model space
    cv::Vec3f base;       // diffuse RGB: the material's Kd, else 0.8 gray
    int32_t texture;      // into textures_ when every corner has texture coordinates, else -1
    bool allUvs;          // every corner has texture coordinates
  };

  const Scene& scene_;
  ShadingMode mode_;
  std::vector<CornerData> corners_;  // per mesh corner (Mesh::corners order)
  bool triangles_ = true;            // every mesh face has 3 corners: face f's are 3f to 3f + 2
  std::vector<FaceData> faces_;      // per mesh face
  // The textures faces use, each framed as FaceSurface says.
  struct Texture {
    std::vector<uint32_t, UninitializedAllocator<uint32_t>> texels;  // 0x00RRGGBB, row 0 on top
    int width = 0, height = 0;
  };
  std::vector<Texture> textures_;
  std::vector<SurfaceTexture> textureViews_;  // textures_ as SurfaceFrame::textures reads them
  std::vector<int32_t> instanceTextures_;     // per instance: its object's texture, else -1

  // Per frame.
  const std::vector<Mat4>* modelView_ = nullptr;
  SurfaceFrame frame_;
  double rayOriginX_ = 0.0, rayOriginY_ = 0.0, rayScaleX_ = 0.0, rayScaleY_ = 0.0;
  int width_ = 0, height_ = 0;  // samples
  struct Cached {
    uint32_t stamp = 0;  // frame in which the entry was set up
    uint32_t index = 0;  // into records_
  };
  uint32_t stamp_ = 0;
  std::vector<Cached> cache_;
  std::vector<SurfaceRecord, UninitializedAllocator<SurfaceRecord>> records_;
  std::vector<SurfaceFan, UninitializedAllocator<SurfaceFan>> fans_;  // polygons' fans
  // Of setUpFaces(): the batch's faces in order of their first row, those of row y at
  // rowOrder_[rowStart_[y - 1], rowStart_[y]) (from 0 for row 0), their records from
  // batchFirstRecord_ on in the same order; and scratch.
  std::vector<uint32_t> rowStart_, rowOrder_, firstFan_;
  size_t batchFirstRecord_ = 0;
  Scratch scratch_;         // of setUp()
  bool batchDone_ = false;  // setUpFaces() ran in this frame
  bool batched_ = false;    // and set up every face of its geometry
  bool byRows_ = false;     // setUpFaces() set the batch up, in order of first row
};

}  // namespace zrender
