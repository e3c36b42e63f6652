#pragma once

#include "zrender/raster/RasterRules.hpp"
#include "zrender/scene/Transforms.hpp"
#include "zrender/transform/VertexProjection.hpp"

namespace zrender {

// What the box of an instance's positions tells, for certain, about all its vertices in a
// frame: whether they are all outside one and the same plane of the view volume (then every
// face would be clipped away), and a window depth none of them is nearer than.
struct InstanceView {
  bool outside = false;
  float nearest = 0.0f;  // 0 when the box reaches the eye plane
  SampleRect area;       // with nearest > 0: the box's samples in the image, widened by 2
};

// The view of the model-space box `bounds` under `mvp` (model to clip space).
InstanceView viewOfInstance(const Mat4& mvp, const Box3& bounds, const VertexViewport& viewport);

}  // namespace zrender
