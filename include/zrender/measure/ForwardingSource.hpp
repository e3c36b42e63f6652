#pragma once

#include "zrender/transform/GeometrySource.hpp"

namespace zrender {

// A GeometrySource that passes every call on to another: the base of the measurements'
// sources, which change one call each.
class ForwardingSource : public GeometrySource {
 public:
  explicit ForwardingSource(GeometrySource& inner) : inner_(inner) {}
  void beginFrame(const Camera& camera) override { inner_.beginFrame(camera); }
  void pull(const FaceRequest& request, FrameGeometry& out,
            std::vector<FrameGeometry>* parts = nullptr) override {
    inner_.pull(request, out, parts);
  }
  void prefetch(const FaceRequest& request) const override { inner_.prefetch(request); }
  InstanceView viewOfInstance(uint32_t instance) const override {
    return inner_.viewOfInstance(instance);
  }
  double transformMs() const override { return inner_.transformMs(); }

 protected:
  GeometrySource& inner_;
};

}  // namespace zrender
