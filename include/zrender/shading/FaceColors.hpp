#pragma once

#include <cstdint>
#include <vector>

#include "zrender/base/Threads.hpp"
#include "zrender/raster/FrameGeometry.hpp"
#include "zrender/scene/Scene.hpp"
#include "zrender/scene/ShadingMode.hpp"

namespace zrender {

// The color of each face in the modes where a face has one color: `id`, `random`, `flat`, and
// `normal` for a model without vertex normals. Computed once per face and frame, on first
// sight, or ahead into a table (prepare()) when pixels are shaded with one color per face.
class FaceColors {
 public:
  FaceColors(const Scene& scene, ShadingMode mode);

  // Starts a frame: `modelView` per instance (kept by reference until the next begin()), the
  // packed `background`, and `faces` (empty: unknown), whose parts hold every face that may be
  // in the buffer by the time prepare() is called.
  void begin(const std::vector<Mat4>& modelView, uint32_t background, const FaceParts& faces);

  // Face `faceId`'s packed color (0x00RRGGBB), computed on first sight in the frame.
  uint32_t color(uint32_t faceId);
  // The same computed anew, writing nothing: for several threads at once.
  uint32_t uncachedColor(uint32_t faceId) const;

  // How pixels of one color per face look their color up, decided at the first prepare() of a
  // frame for a buffer of `samples` samples.
  enum class Lookup {
    ById,        // table()[id + 1]; table()[0] is the background
    ByMeshFace,  // table()[id % mesh faces]: normal colors of a grid whose instances share
                 // their rotation
    OnSight,     // color(id)
  };
  // Decides the look-up and brings the table up to date with the geometry's faces (computed
  // by `threads` when given).
  Lookup prepare(size_t samples, const Threads* threads = nullptr);
  const uint32_t* table() const { return table_.data(); }

 private:
  uint32_t normalColor(const Mat4& modelView, uint32_t local) const;  // of a mesh face

  const Scene& scene_;
  ShadingMode mode_;
  std::vector<Vec3> faceNormals_;  // model space, per mesh face (Newell, unit or zero)

  // Per frame.
  const std::vector<Mat4>* modelView_ = nullptr;
  FaceParts faces_;
  uint32_t background_ = 0;
  // Every instance's model-view rotation (3 x 3) equals the first one's, as for grids.
  bool sharedRotation_ = false;
  struct Cached {
    uint32_t stamp = 0;  // frame in which the entry was computed
    uint32_t color = 0;
  };
  uint32_t frame_ = 0;
  std::vector<Cached> cache_;
  bool decided_ = false;
  Lookup lookup_ = Lookup::OnSight;
  size_t tableFaces_ = 0;        // geometry faces whose colors the ById table holds
  std::vector<uint32_t> table_;  // ById: [0] background, [id + 1]; ByMeshFace: per mesh face
};

}  // namespace zrender
