#include "zrender/shading/NormalImage.hpp"

#include <cmath>
#include <optional>
#include <vector>

#include "SurfaceSample.hpp"
#include "zrender/shading/ShadingModel.hpp"
#include "zrender/shading/SurfaceSetup.hpp"

namespace zrender {

cv::Mat normalImage(const Scene& scene, const FrameBuffer& fb, const Camera& camera, int scale) {
  std::vector<Mat4> modelView;
  for (uint32_t k = 0; k < scene.instanceCount(); ++k)
    modelView.push_back(camera.view * scene.modelMatrix(k));
  // As the Shader chooses: the surface kernel's interpolated normal where the model has
  // vertex normals, else the face's own.
  std::optional<SurfaceSetup> surface;
  if (scene.mesh->hasNormals()) {
    surface.emplace(scene, ShadingMode::Normal);
    surface->begin(modelView, camera, fb.width(), fb.height());
  }
  const int width = fb.width() / scale, height = fb.height() / scale;
  cv::Mat out(height, width, CV_32FC3, cv::Scalar::all(0.0));
  for (int y = 0; y < height; ++y) {
    float* row = out.ptr<float>(y);
    for (int x = 0; x < width; ++x) {
      // The pixel's nearest sample, the smallest key, first in row order among equals.
      int sx = x * scale, sy = y * scale;
      DepthKey key = fb.row(sy)[sx];
      for (int j = 0; j < scale; ++j) {
        for (int i = 0; i < scale; ++i) {
          const DepthKey k = fb.row(y * scale + j)[x * scale + i];
          if (k < key) key = k, sx = x * scale + i, sy = y * scale + j;
        }
      }
      const uint32_t id = keyFaceId(key);
      if (id == kBackgroundId) continue;
      Vec3 n;
      if (surface) {
        const FaceSurface& face = surface->surface(id);
        float m[3], uv[2];
        const float length =
            std::sqrt(surface::surfaceAt(face, surface->fans(face), sx, sy, m, uv));
        n = Vec3(m[0] / length, m[1] / length, m[2] / length);
      } else {
        const FaceRef ref = scene.locate(id);
        n = transformDirection(modelView[ref.instance], newellNormal(*scene.mesh, ref.meshFace));
        const double length = cv::norm(n);
        n = length > 0.0 ? n / length : Vec3(0, 0, 1);
      }
      row[3 * x + 0] = float(n[2]);
      row[3 * x + 1] = float(n[1]);
      row[3 * x + 2] = float(n[0]);
    }
  }
  return out;
}

cv::Mat normalImage16(const cv::Mat& normals) {
  cv::Mat out(normals.rows, normals.cols, CV_16UC3, cv::Scalar::all(0));
  for (int y = 0; y < normals.rows; ++y) {
    const float* in = normals.ptr<float>(y);
    uint16_t* row = out.ptr<uint16_t>(y);
    for (int i = 0; i < 3 * normals.cols; i += 3) {
      if (in[i] == 0.0f && in[i + 1] == 0.0f && in[i + 2] == 0.0f) continue;  // no face
      for (int c = 0; c < 3; ++c)
        row[i + c] = uint16_t(std::lround((double(in[i + c]) + 1.0) * 0.5 * 65535.0));
    }
  }
  return out;
}

}  // namespace zrender
