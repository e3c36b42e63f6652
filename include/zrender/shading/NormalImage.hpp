#pragma once

#include <optional>
#include <vector>

#include <opencv2/core/mat.hpp>

#include "zrender/raster/FrameBuffer.hpp"
#include "zrender/scene/Camera.hpp"
#include "zrender/scene/Scene.hpp"
#include "zrender/shading/SurfaceSetup.hpp"

namespace zrender {

// The view-space unit normal at each pixel (at the sample nearestSample() names, the one the
// id and depth images show), as the `normal` shading mode sees it: the vertex normals
// interpolated where the model has them, else the face's. What depends on the model alone is
// made once, for every frame after.
class NormalImage {
 public:
  explicit NormalImage(const Scene& scene);

  // 32-bit float, 3 channels in OpenCV's order, so that an image file's R, G and B hold x, y
  // and z (channel 0 is z); 0, 0, 0 where no face is.
  cv::Mat render(const FrameBuffer& fb, const Camera& camera, int sampleScale);

 private:
  const Scene& scene_;
  std::optional<SurfaceSetup> surface_;  // with vertex normals
  std::vector<Vec3> faceNormals_;        // without: per mesh face, model space (Newell)
};

// `normals` as a 16-bit PNG holds them: round((n + 1) / 2 * 65535) per channel, 0 where no
// face is.
cv::Mat normalImage16(const cv::Mat& normals);

}  // namespace zrender
