#pragma once

#include "zrender/scene/Camera.hpp"
#include "zrender/scene/Scene.hpp"

namespace zrender {

// Sample rows [begin, end) of an image.
struct RowSpan {
  int begin = 0, end = 0;
};

// The sample rows of a `heightSamples`-row image that the scene's instances may cover seen
// through `camera`: those of their model's box (SceneModel::box), instance by instance, widened
// by a row; every row when a box reaches the near plane or behind the eye. For cutting the
// image into bands where the work is (threads): nothing any result depends on.
RowSpan screenRows(const Scene& scene, const Camera& camera, int heightSamples);

}  // namespace zrender
