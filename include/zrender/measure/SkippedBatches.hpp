#pragma once

#include <cstddef>
#include <vector>

#include "zrender/measure/ForwardingSource.hpp"

namespace zrender {

// A source that counts the batches an algorithm pulls and, for those marked in `skip`, gives
// nothing and costs nothing, as if the algorithm had culled them perfectly and for free
// (CullingBound: the octree's leaves that hold no visible face). Empty `skip`: none skipped.
class SkippedBatches : public ForwardingSource {
 public:
  SkippedBatches(GeometrySource& inner, std::vector<bool> skip, size_t& pulled)
      : ForwardingSource(inner), skip_(std::move(skip)), pulled_(pulled) {}

  void pull(const FaceRequest& request, FrameGeometry& out,
            std::vector<FrameGeometry>* parts = nullptr) override {
    if (request.scope == FaceRequest::Scope::Batch) {
      ++pulled_;
      if (request.index < skip_.size() && skip_[request.index]) return;
    }
    inner_.pull(request, out, parts);
  }

 private:
  std::vector<bool> skip_;
  size_t& pulled_;  // batches pulled, skipped ones included
};

}  // namespace zrender
