#include "zrender/shading/NormalImage.hpp"

#include <cmath>
#include <vector>

#include "SurfaceSample.hpp"
#include "zrender/shading/ShadingModel.hpp"

namespace zrender {

NormalImage::NormalImage(const Scene& scene) : scene_(scene) {
  // As the Shader chooses: the surface kernel's interpolated normal where the model has
  // vertex normals, else the face's own.
  const Mesh& mesh = *scene.mesh;
  if (mesh.hasNormals()) {
    surface_.emplace(scene, ShadingMode::Normal);
    return;
  }
  faceNormals_.resize(mesh.faceCount());
  for (size_t f = 0; f < mesh.faceCount(); ++f) faceNormals_[f] = newellNormal(mesh, f);
}

cv::Mat NormalImage::render(const FrameBuffer& fb, const Camera& camera, int scale) {
  std::vector<Mat4> modelView;
  for (uint32_t k = 0; k < scene_.instanceCount(); ++k)
    modelView.push_back(camera.view * scene_.modelMatrix(k));
  if (surface_) surface_->begin(modelView, camera, fb.width(), fb.height());
  const int width = fb.width() / scale, height = fb.height() / scale;
  cv::Mat out(height, width, CV_32FC3, cv::Scalar::all(0.0));
  for (int y = 0; y < height; ++y) {
    float* row = out.ptr<float>(y);
    for (int x = 0; x < width; ++x) {
      const PixelSample sample = nearestSample(fb, scale, x, y);
      const uint32_t id = keyFaceId(sample.key);
      if (id == kBackgroundId) continue;
      Vec3 n;
      if (surface_) {
        const FaceSurface& face = surface_->surface(id);
        float m[3], uv[2];
        const float length =
            std::sqrt(surface::surfaceAt(face, surface_->fans(face), sample.x, sample.y, m, uv));
        n = Vec3(m[0] / length, m[1] / length, m[2] / length);
      } else {
        const FaceRef ref = scene_.locate(id);
        n = transformDirection(modelView[ref.instance], faceNormals_[ref.meshFace]);
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
