#pragma once

#include <functional>

#include "zrender/base/Clock.hpp"
#include "zrender/measure/ForwardingSource.hpp"

namespace zrender {

// A source that passes on only the triangles for which `keep` is true, as if an algorithm had
// culled the others perfectly (CullingBound: the visible faces alone; RowOcclusion: one row of
// a grid alone). The time it takes to leave them out is booked as transform time, so that the
// raster is the drawing of the kept triangles alone.
class KeptTriangles : public ForwardingSource {
 public:
  using Keep = std::function<bool(const ScreenTriangle&)>;
  KeptTriangles(GeometrySource& inner, Keep keep)
      : ForwardingSource(inner), keep_(std::move(keep)) {}

  void beginFrame(const Camera& camera) override {
    ownMs_ = 0.0;
    inner_.beginFrame(camera);
  }
  void pull(const FaceRequest& request, FrameGeometry& out,
            std::vector<FrameGeometry>* parts = nullptr) override {
    const size_t first = out.triangles.size();
    inner_.pull(request, out, parts);
    if (!parts) {
      leaveOut(out, first);
      return;
    }
    for (FrameGeometry& part : *parts) leaveOut(part, 0);
  }
  double transformMs() const override { return inner_.transformMs() + ownMs_; }

 private:
  // Removes the triangles from `first` on that are not kept.
  void leaveOut(FrameGeometry& out, size_t first);

  Keep keep_;
  double ownMs_ = 0.0;
};

}  // namespace zrender
