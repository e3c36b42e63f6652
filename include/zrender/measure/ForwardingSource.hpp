#pragma once

#include "zrender/transform/GeometrySource.hpp"

namespace zrender {

// A GeometrySource that passes every call on to another: the base of the measurements'
// sources, which change one call each.
class ForwardingSource : public GeometrySource {
 public:
  explicit ForwardingSource(GeometrySource& inner) : inner_(inner) {}
  void beginFrame(const Camera& camera) override { inner_.beginFrame(camera); }
  void pullAll(FrameGeometry& out) override { inner_.pullAll(out); }
  void pullInstance(uint32_t instance, FrameGeometry& out, TriangleFilter* filter) override {
    inner_.pullInstance(instance, out, filter);
  }
  void pullBatch(uint32_t batch, FrameGeometry& out) override { inner_.pullBatch(batch, out); }
  void prefetchBatch(uint32_t batch) const override { inner_.prefetchBatch(batch); }
  double transformMs() const override { return inner_.transformMs(); }

 protected:
  GeometrySource& inner_;
};

}  // namespace zrender
