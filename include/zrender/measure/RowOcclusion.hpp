#pragma once

#include <cstddef>
#include <vector>

#include "zrender/scene/Camera.hpp"
#include "zrender/scene/Scene.hpp"

namespace zrender {

// One row of a grid scene: the instances that share a grid offset along z (for `crowd`, a row
// of bunnies across the view), and how much of it the rows in front hide.
struct RowOcclusion {
  double offsetZ = 0.0;       // the row's grid offset along z, model units
  size_t samplesAlone = 0;    // samples its faces cover when drawn without the other rows
  size_t samplesVisible = 0;  // samples it owns in the frame of the whole scene
};

// Each row of the scene, nearest the eye first (by its instances' mean offset along the view
// direction), measured with the z-buffer. What `crowd` was asked for ("each row hides most
// of the ones behind") is 1 - samplesVisible / samplesAlone close to 1 for rows after the
// first. Measured by `zrender-culling-bound --rows`, a developer tool, not part of `zrender`.
std::vector<RowOcclusion> measureRowOcclusion(const Scene& scene, const Camera& camera);

}  // namespace zrender
