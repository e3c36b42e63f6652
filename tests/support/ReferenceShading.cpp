#include "support/ReferenceShading.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/core/mat.hpp>

#include "zrender/shading/FaceColors.hpp"
#include "zrender/shading/ShadingModel.hpp"

namespace zrender::test {

namespace {

// Blinn–Phong with the light at the eye (so L = V = H): ambient 0.1, diffuse 0.9, white
// specular 0.3 with exponent 64; `n` and `toEye` unit vectors in one space.
cv::Vec3f blinnPhong(const cv::Vec3f& base, const Vec3& n, const Vec3& toEye) {
  const double diffuse = std::max(0.0, n.dot(toEye));
  const double specular = std::pow(diffuse, 64.0);
  const double ambient = 0.1;
  cv::Vec3f c;
  for (int i = 0; i < 3; ++i)
    c[i] = float(base[i] * (ambient + (1.0 - ambient) * diffuse) + 0.3 * specular);
  return c;
}

}  // namespace

ReferenceSurfaceShading::ReferenceSurfaceShading(const Scene& scene, ShadingMode mode)
    : scene_(scene), mode_(mode) {
  const Mesh& mesh = *scene.mesh;
  faceNormals_.resize(mesh.faceCount());
  for (size_t f = 0; f < mesh.faceCount(); ++f) faceNormals_[f] = newellNormal(mesh, f);
  if ((mode == ShadingMode::Phong || mode == ShadingMode::Texture) && !mesh.hasNormals()) {
    // Smooth normals: area-weighted sum of the normals of the faces around each position.
    smoothNormals_.assign(mesh.positions.size(), Vec3(0, 0, 0));
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
      const Vec3 weighted = newellSum(mesh, f);
      const Corner* c = mesh.faceCorners(f);
      for (uint32_t i = 0; i < mesh.cornerCount(f); ++i)
        smoothNormals_[size_t(c[i].position)] += weighted;
    }
    for (Vec3& n : smoothNormals_) n = safeNormalize(n);
  }
}

void ReferenceSurfaceShading::begin(const std::vector<Mat4>& modelView, const Camera& camera,
                                    int widthSamples, int heightSamples) {
  modelView_ = &modelView;
  if (cache_.size() != scene_.faceCount()) {
    cache_.assign(scene_.faceCount(), Cached());
    frame_ = 0;
  }
  ++frame_;
  faceShade_.clear();
  cornerPos_.clear();
  cornerNormal_.clear();
  cornerUv_.clear();
  // View-space ray through a sample centre: x_view / -z_view = x_ndc / P00.
  rayScaleX_ = 2.0 / widthSamples / camera.projection(0, 0);
  rayScaleY_ = 2.0 / heightSamples / camera.projection(1, 1);
  rayOriginX_ = -1.0 / camera.projection(0, 0);
  rayOriginY_ = 1.0 / camera.projection(1, 1);
}

uint32_t ReferenceSurfaceShading::faceShadeIndex(uint32_t faceId) {
  Cached& entry = cache_[faceId];
  if (entry.stamp == frame_) return entry.index;
  const Mesh& mesh = *scene_.mesh;
  const uint32_t nf = uint32_t(mesh.faceCount());
  const uint32_t instance = faceId / nf, local = faceId % nf;
  const Mat4& mv = (*modelView_)[instance];
  const Corner* c = mesh.faceCorners(local);
  const uint32_t n = mesh.cornerCount(local);
  FaceShade fs;
  fs.first = uint32_t(cornerPos_.size());
  fs.count = n;
  bool allNormals = mesh.hasNormals(), allUvs = mesh.hasTexcoords();
  for (uint32_t i = 0; i < n; ++i) {
    allNormals &= c[i].normal >= 0;
    allUvs &= c[i].texcoord >= 0;
  }
  for (uint32_t i = 0; i < n; ++i) {
    cornerPos_.push_back(transformPoint(mv, mesh.positions[size_t(c[i].position)]));
    Vec3 normal;
    if (allNormals)
      normal = mesh.normals[size_t(c[i].normal)];
    else if (!smoothNormals_.empty())
      normal = smoothNormals_[size_t(c[i].position)];
    else
      normal = faceNormals_[local];
    cornerNormal_.push_back(safeNormalize(transformDirection(mv, normal)));
    cornerUv_.push_back(allUvs ? mesh.texcoords[size_t(c[i].texcoord)] : cv::Vec2d(0, 0));
  }
  const Vec3 geometric = transformDirection(mv, faceNormals_[local]);
  fs.flip = geometric.dot(-cornerPos_[fs.first]) < 0.0;
  const int32_t material = local < mesh.faceMaterial.size() ? mesh.faceMaterial[local] : -1;
  fs.base = local < mesh.faceColors.size() ? mesh.faceColors[local]
            : material >= 0                ? mesh.materials[size_t(material)].diffuse
                                           : cv::Vec3f(0.8f, 0.8f, 0.8f);
  fs.texture = mode_ == ShadingMode::Texture && allUvs ? &scene_.textureOf(local) : nullptr;
  if (fs.texture && fs.texture->empty()) fs.texture = nullptr;
  entry.stamp = frame_;
  entry.index = uint32_t(faceShade_.size());
  faceShade_.push_back(fs);
  return entry.index;
}

cv::Vec3f ReferenceSurfaceShading::sampleTexture(const cv::Mat& t, const cv::Vec2d& uv) const {
  // Bilinear, wrapping; v = 0 is the bottom row of the image (OBJ convention).
  const double u = uv[0] - std::floor(uv[0]), v = uv[1] - std::floor(uv[1]);
  const double x = u * t.cols - 0.5, y = (1.0 - v) * t.rows - 0.5;
  const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  const double fx = x - x0, fy = y - y0;
  auto at = [&](int xi, int yi) {
    xi = ((xi % t.cols) + t.cols) % t.cols;
    yi = ((yi % t.rows) + t.rows) % t.rows;
    return t.at<cv::Vec3b>(yi, xi);
  };
  const cv::Vec3b a = at(x0, y0), b = at(x0 + 1, y0), c = at(x0, y0 + 1), d = at(x0 + 1, y0 + 1);
  cv::Vec3f rgb;
  for (int i = 0; i < 3; ++i) {
    const double top = a[2 - i] * (1 - fx) + b[2 - i] * fx;
    const double bottom = c[2 - i] * (1 - fx) + d[2 - i] * fx;
    rgb[i] = float((top * (1 - fy) + bottom * fy) / 255.0);
  }
  return rgb;
}

uint32_t ReferenceSurfaceShading::color(uint32_t faceId, int x, int y) {
  const Vec3 dir(rayOriginX_ + (x + 0.5) * rayScaleX_, rayOriginY_ - (y + 0.5) * rayScaleY_, -1.0);
  const FaceShade& fs = faceShade_[faceShadeIndex(faceId)];
  const Vec3* pos = cornerPos_.data() + fs.first;
  // Intersect the view ray (from the eye at the origin) with the fan triangles of the face;
  // take the first that contains the hit, else the one it misses least.
  double bestU = 0, bestV = 0, bestT = 1, bestMiss = HUGE_VAL;
  uint32_t best = 1;
  for (uint32_t j = 1; j + 1 < fs.count; ++j) {
    const Vec3 e1 = pos[j] - pos[0], e2 = pos[j + 1] - pos[0];
    const Vec3 pvec = dir.cross(e2);
    const double det = e1.dot(pvec);
    if (det == 0.0) continue;
    const Vec3 tvec = -pos[0];
    const double u = tvec.dot(pvec) / det;
    const Vec3 qvec = tvec.cross(e1);
    const double v = dir.dot(qvec) / det;
    const double t = e2.dot(qvec) / det;
    const double miss = std::max({-u, -v, u + v - 1.0, 0.0});
    if (miss < bestMiss) {
      bestMiss = miss, bestU = u, bestV = v, bestT = t, best = j;
      if (miss == 0.0) break;
    }
  }
  // Samples just outside a face (its snapped edge) get the nearest point's attributes.
  double u = std::max(bestU, 0.0), v = std::max(bestV, 0.0);
  if (u + v > 1.0) {
    const double s = u + v;
    u /= s, v /= s;
  }
  const double w0 = 1.0 - u - v;
  const uint32_t i1 = fs.first + best, i2 = fs.first + best + 1;
  Vec3 n = cornerNormal_[fs.first] * w0 + cornerNormal_[i1] * u + cornerNormal_[i2] * v;
  n = safeNormalize(n);
  cv::Vec3f rgb;
  if (mode_ == ShadingMode::Normal) {
    rgb = cv::Vec3f(float((n[0] + 1) * 0.5), float((n[1] + 1) * 0.5), float((n[2] + 1) * 0.5));
  } else {
    if (fs.flip) n = -n;
    cv::Vec3f base = fs.base;
    if (fs.texture) {
      const cv::Vec2d uv = cornerUv_[fs.first] * w0 + cornerUv_[i1] * u + cornerUv_[i2] * v;
      base = sampleTexture(*fs.texture, uv);
    }
    const Vec3 toEye = safeNormalize(-(dir * bestT));
    rgb = blinnPhong(base, n, toEye);
  }
  auto q = [](float c) { return uint32_t(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f)); };
  return (q(rgb[0]) << 16) | (q(rgb[1]) << 8) | q(rgb[2]);
}

cv::Mat referenceImage(const Scene& scene, const Camera& camera, const FrameBuffer& fb,
                       int sampleScale) {
  const ShadingMode mode = scene.settings.shading;
  std::vector<Mat4> modelView;
  for (uint32_t k = 0; k < scene.instanceCount(); ++k)
    modelView.push_back(camera.view * scene.modelMatrix(k));
  const auto& bg = scene.settings.background;
  const uint32_t background =
      mode == ShadingMode::Id ? 0 : (uint32_t(bg[0]) << 16) | (uint32_t(bg[1]) << 8) | bg[2];
  const bool surfaceMode = mode == ShadingMode::Phong || mode == ShadingMode::Texture ||
                           (mode == ShadingMode::Normal && scene.mesh->hasNormals());
  ReferenceSurfaceShading surface(scene, mode);
  surface.begin(modelView, camera, fb.width(), fb.height());
  FaceColors faceColors(scene, mode);
  faceColors.begin(modelView, background, FaceParts());
  float depthLo = 1.0f, depthHi = 0.0f;
  for (size_t i = 0; i < fb.size(); ++i) {
    if (keyFaceId(fb.data()[i]) == kBackgroundId) continue;
    depthLo = std::min(depthLo, keyDepth(fb.data()[i]));
    depthHi = std::max(depthHi, keyDepth(fb.data()[i]));
  }
  const double depthRange = depthHi > depthLo ? double(depthHi) - depthLo : 1.0;
  const auto sampleColor = [&](DepthKey key, int x, int y) {
    const uint32_t id = keyFaceId(key);
    if (id == kBackgroundId) return background;
    if (mode == ShadingMode::Depth) {
      const double g = 1.0 - (double(keyDepth(key)) - depthLo) / depthRange;
      return packRgb(g, g, g);
    }
    return surfaceMode ? surface.color(id, x, y) : faceColors.color(id);
  };
  cv::Mat image(fb.height() / sampleScale, fb.width() / sampleScale, CV_8UC3);
  for (int y = 0; y < image.rows; ++y) {
    for (int x = 0; x < image.cols; ++x) {
      uint32_t c = 0;
      if (sampleScale == 1) {
        c = sampleColor(fb.row(y)[x], x, y);
      } else if (mode == ShadingMode::Id) {
        const DepthKey* r0 = fb.row(2 * y);
        const DepthKey* r1 = fb.row(2 * y + 1);
        c = sampleColor(std::min({r0[2 * x], r0[2 * x + 1], r1[2 * x], r1[2 * x + 1]}), 0, 0);
      } else {
        uint32_t sum[3] = {0, 0, 0};
        for (int s = 0; s < 4; ++s) {
          const int sx = 2 * x + s % 2, sy = 2 * y + s / 2;
          const uint32_t sc = sampleColor(fb.row(sy)[sx], sx, sy);
          for (int i = 0; i < 3; ++i) sum[i] += (sc >> (8 * i)) & 0xFF;
        }
        c = ((sum[2] + 2) / 4) << 16 | ((sum[1] + 2) / 4) << 8 | (sum[0] + 2) / 4;
      }
      image.at<cv::Vec3b>(y, x) = cv::Vec3b(uchar(c), uchar(c >> 8), uchar(c >> 16));
    }
  }
  return image;
}

}  // namespace zrender::test
