#include "zrender/shading/Shader.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace zrender {

namespace {

// Packs an RGB color in 0..1 as 0x00RRGGBB, rounding to nearest.
uint32_t packRgb(double r, double g, double b) {
  auto q = [](double v) { return uint32_t(std::clamp(v, 0.0, 1.0) * 255.0 + 0.5); };
  return (q(r) << 16) | (q(g) << 8) | q(b);
}

// Newell's sum over a face's corners (model space): the face normal times twice its area.
Vec3 newellSum(const Mesh& mesh, size_t face) {
  const Corner* c = mesh.faceCorners(face);
  const uint32_t n = mesh.cornerCount(face);
  Vec3 normal(0, 0, 0);
  for (uint32_t i = 0; i < n; ++i) {
    const Vec3& p = mesh.positions[size_t(c[i].position)];
    const Vec3& q = mesh.positions[size_t(c[(i + 1) % n].position)];
    normal += Vec3((p[1] - q[1]) * (p[2] + q[2]), (p[2] - q[2]) * (p[0] + q[0]),
                   (p[0] - q[0]) * (p[1] + q[1]));
  }
  return normal;
}

// The unit normal of a face; zero for a degenerate face.
Vec3 newellNormal(const Mesh& mesh, size_t face) {
  const Vec3 normal = newellSum(mesh, face);
  const double len = cv::norm(normal);
  return len > 0.0 ? normal / len : Vec3(0, 0, 0);
}

Vec3 safeNormalize(const Vec3& v) {
  const double len = cv::norm(v);
  return len > 0.0 ? v / len : Vec3(0, 0, 1);
}

// Blinn–Phong with the light at the eye (so L = V = H), in 0..1 RGB.
cv::Vec3f blinnPhong(const cv::Vec3f& base, const Vec3& n, const Vec3& toEye) {
  const double diffuse = std::max(0.0, n.dot(toEye));
  const double specular = std::pow(diffuse, 64.0);
  const double ambient = 0.1;
  cv::Vec3f c;
  for (int i = 0; i < 3; ++i)
    c[i] = float(base[i] * (ambient + (1.0 - ambient) * diffuse) + 0.3 * specular);
  return c;
}

// Writes the pixels of rows [firstRow, endRow) of `color` (CV_8UC3, the size of `fb`) as
// colorOf(key) (0x00RRGGBB).
template <typename ColorOf>
void shadeRows(const FrameBuffer& fb, int firstRow, int endRow, uint32_t background, cv::Mat& color,
               ColorOf colorOf) {
  const int width = fb.width();
  const uint32_t backgroundWords[3] = {background | background << 24,
                                       background >> 8 | background << 16,
                                       background >> 16 | background << 8};
  for (int y = firstRow; y < endRow; ++y) {
    uchar* out = color.ptr<uchar>(y);
    const DepthKey* row = fb.row(y);
    // Four pixels (12 bytes: B, G, R each) as three separate 4-byte stores, then the rest one
    // by one. Measured: 4-byte stores beat one 8-byte and one 4-byte store by 3x here. Four
    // background pixels in a row (most of an image, in long runs) skip the look-ups.
    int x = 0;
    for (; x + 4 <= width; x += 4) {
      const uint32_t ids =
          keyFaceId(row[x]) & keyFaceId(row[x + 1]) & keyFaceId(row[x + 2]) & keyFaceId(row[x + 3]);
      if (ids == kBackgroundId) {
        for (int i = 0; i < 3; ++i) std::memcpy(out + 3 * x + 4 * i, &backgroundWords[i], 4);
        continue;
      }
      const uint32_t c0 = colorOf(row[x]), c1 = colorOf(row[x + 1]);
      const uint32_t c2 = colorOf(row[x + 2]), c3 = colorOf(row[x + 3]);
      const uint32_t words[3] = {c0 | c1 << 24, c1 >> 8 | c2 << 16, c2 >> 16 | c3 << 8};
      for (int i = 0; i < 3; ++i) std::memcpy(out + 3 * x + 4 * i, &words[i], 4);
    }
    for (; x < width; ++x) {
      const uint32_t c = colorOf(row[x]);
      out[3 * x + 0] = uchar(c);
      out[3 * x + 1] = uchar(c >> 8);
      out[3 * x + 2] = uchar(c >> 16);
    }
  }
}

// shadeRows with one color per face, colorOfFace(id) (0x00RRGGBB), asked once per run of a
// face's pixels along a row: a face usually covers a few pixels in a row.
template <typename ColorOfFace>
void shadeFaceRuns(const FrameBuffer& fb, int firstRow, int endRow, uint32_t background,
                   cv::Mat& color, ColorOfFace colorOfFace) {
  uint32_t lastId = kBackgroundId, lastColor = background;
  shadeRows(fb, firstRow, endRow, background, color, [&](DepthKey key) {
    const uint32_t id = keyFaceId(key);
    if (id == lastId) return lastColor;
    lastId = id;
    return lastColor = id == kBackgroundId ? background : colorOfFace(id);
  });
}

}  // namespace

uint32_t randomFaceColor(uint32_t faceId) {
  // splitmix32-style finalizer: neighbouring ids get unrelated colors.
  uint32_t h = faceId * 0x9E3779B9u + 0x7F4A7C15u;
  h = (h ^ (h >> 16)) * 0x85EBCA6Bu;
  h = (h ^ (h >> 13)) * 0xC2B2AE35u;
  h ^= h >> 16;
  // Keep colors away from black so faces stand out from the default background.
  return (h & 0x00FFFFFFu) | 0x00303030u;
}

Shader::Shader(const Scene& scene, ShadingMode mode) : scene_(scene), mode_(mode) {
  const Mesh& mesh = *scene.mesh;
  faceNormals_.resize(mesh.faceCount());
  for (size_t f = 0; f < mesh.faceCount(); ++f) faceNormals_[f] = newellNormal(mesh, f);
  perSample_ = mode == ShadingMode::Phong || mode == ShadingMode::Texture ||
               (mode == ShadingMode::Normal && mesh.hasNormals());
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

uint32_t Shader::normalColor(const Mat4& modelView, uint32_t local) const {
  // Rigid transform of a unit (or zero) normal: no renormalization needed.
  const Vec3 n = transformDirection(modelView, faceNormals_[local]);
  return packRgb((n[0] + 1) * 0.5, (n[1] + 1) * 0.5, (n[2] + 1) * 0.5);
}

uint32_t Shader::faceColor(uint32_t faceId) {
  // Colors of the id alone: a few operations, cheaper than a look-up in a table of every face.
  if (mode_ == ShadingMode::Id || mode_ == ShadingMode::Random) return uncachedFaceColor(faceId);
  const uint32_t nf = uint32_t(scene_.mesh->faceCount());
  // Normal colors of instances that share their rotation are those of the mesh face: one
  // entry per mesh face, which stays in cache where one per face of a big grid does not.
  FaceCache& entry = cache_[mode_ == ShadingMode::Normal && sharedRotation_ ? faceId % nf : faceId];
  if (entry.stamp == frame_) return entry.data;
  entry.stamp = frame_;
  entry.data = uncachedFaceColor(faceId);
  return entry.data;
}

uint32_t Shader::uncachedFaceColor(uint32_t faceId) const {
  if (mode_ == ShadingMode::Id) {
    const uint32_t v = faceId + 1;  // R = low byte, G = middle, B = high (SPEC §6)
    return ((v & 0xFF) << 16) | (((v >> 8) & 0xFF) << 8) | ((v >> 16) & 0xFF);
  }
  if (mode_ == ShadingMode::Random) return randomFaceColor(faceId);
  const uint32_t nf = uint32_t(scene_.mesh->faceCount());
  const uint32_t instance = faceId / nf, local = faceId % nf;
  uint32_t color = 0;
  switch (mode_) {
    case ShadingMode::Normal:
      color = normalColor(modelView_[instance], local);
      break;
    case ShadingMode::Flat: {
      // Lambert term of the face normal under a light at the eye, seen from the centroid.
      const Mesh& mesh = *scene_.mesh;
      const Corner* c = mesh.faceCorners(local);
      const uint32_t n = mesh.cornerCount(local);
      Vec3 centroid(0, 0, 0);
      for (uint32_t i = 0; i < n; ++i) centroid += mesh.positions[size_t(c[i].position)];
      centroid *= 1.0 / std::max<uint32_t>(n, 1);
      const Vec3 p = transformPoint(modelView_[instance], centroid);
      const Vec3 normal = transformDirection(modelView_[instance], faceNormals_[local]);
      const double g = std::abs(normal.dot(safeNormalize(-p)));
      color = packRgb(g, g, g);
      break;
    }
    default:
      break;
  }
  return color;
}

uint32_t Shader::faceShadeIndex(uint32_t faceId) {
  FaceCache& entry = cache_[faceId];
  if (entry.stamp == frame_) return entry.data;
  const Mesh& mesh = *scene_.mesh;
  const uint32_t nf = uint32_t(mesh.faceCount());
  const uint32_t instance = faceId / nf, local = faceId % nf;
  const Mat4& mv = modelView_[instance];
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
  fs.base = material >= 0 ? mesh.materials[size_t(material)].diffuse : cv::Vec3f(0.8f, 0.8f, 0.8f);
  if (mode_ == ShadingMode::Texture && !scene_.texture.empty() && allUvs)
    fs.base = cv::Vec3f(-1, -1, -1);  // marker: sample the texture
  entry.stamp = frame_;
  entry.data = uint32_t(faceShade_.size());
  faceShade_.push_back(fs);
  return entry.data;
}

cv::Vec3f Shader::sampleTexture(const cv::Vec2d& uv) const {
  // Bilinear, wrapping; v = 0 is the bottom row of the image (OBJ convention).
  const cv::Mat& t = scene_.texture;
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

cv::Vec3b Shader::shadeSample(uint32_t faceId, const Vec3& dir) {
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
    if (base[0] < 0.0f) {
      const cv::Vec2d uv = cornerUv_[fs.first] * w0 + cornerUv_[i1] * u + cornerUv_[i2] * v;
      base = sampleTexture(uv);
    }
    const Vec3 toEye = safeNormalize(-(dir * bestT));
    rgb = blinnPhong(base, n, toEye);
  }
  auto q = [](float c) { return uchar(std::lround(std::clamp(c, 0.0f, 1.0f) * 255.0f)); };
  return cv::Vec3b(q(rgb[2]), q(rgb[1]), q(rgb[0]));
}

void Shader::begin(const FrameBuffer& fb, const Camera& camera, int scale, cv::Mat& color,
                   const FrameGeometry* geometry) {
  fb_ = &fb;
  geometry_ = geometry;
  color_ = &color;
  scale_ = scale;
  shadedRows_ = 0;
  color.create(fb.height() / scale, fb.width() / scale, CV_8UC3);
  if (cache_.size() != scene_.faceCount()) {
    cache_.assign(scene_.faceCount(), FaceCache());
    frame_ = 0;
  }
  ++frame_;
  faceShade_.clear();
  cornerPos_.clear();
  cornerNormal_.clear();
  cornerUv_.clear();
  modelView_.clear();
  for (uint32_t k = 0; k < scene_.instanceCount(); ++k)
    modelView_.push_back(camera.view * scene_.modelMatrix(k));
  sharedRotation_ = true;
  for (const Mat4& mv : modelView_)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        sharedRotation_ = sharedRotation_ && mv(i, j) == modelView_[0](i, j);

  // An id image's background is id 0 (SPEC §6), whatever the scene's background color.
  const auto& bg = scene_.settings.background;
  background_ = mode_ == ShadingMode::Id
                    ? 0
                    : (uint32_t(bg[0]) << 16) | (uint32_t(bg[1]) << 8) | uint32_t(bg[2]);

  // View-space ray through a sample centre: x_view / -z_view = x_ndc / P00.
  rayScaleX_ = 2.0 / fb.width() / camera.projection(0, 0);
  rayScaleY_ = 2.0 / fb.height() / camera.projection(1, 1);
  rayOriginX_ = -1.0 / camera.projection(0, 0);
  rayOriginY_ = 1.0 / camera.projection(1, 1);

  perFace_ = scale == 1 && !perSample_ && mode_ != ShadingMode::Depth;
  tableState_ = TableState::Undecided;
  tableFaces_ = 0;
}

void Shader::prepareTable() {
  // The common case (one sample per pixel, one color per face) is a table look-up per pixel,
  // when there are few faces for the pixels (the bunny: 31k front faces, 3.2M pixels):
  // computing the colors of the frame's faces in a row is cheaper than computing them on first
  // sight, where each look-up of the face's normal is a cache miss. Only faces of the frame's
  // geometry can be in the buffer, so only theirs are computed, as they appear.
  if (tableState_ == TableState::Undecided) {
    const size_t faces = geometry_ ? geometry_->faces.size() : scene_.faceCount();
    tableState_ = perFace_ && faces * 16 <= fb_->size() ? TableState::On : TableState::Off;
    const uint32_t meshFaces = uint32_t(scene_.mesh->faceCount());
    if (tableState_ == TableState::Off && perFace_ && mode_ == ShadingMode::Normal &&
        sharedRotation_ && size_t(meshFaces) * 16 <= fb_->size()) {
      // Many faces of a grid (the crowd: 475k transformed, 69k per bunny): normal colors are
      // those of the mesh faces, all computed in a row (normals read in order) into a table
      // that stays in cache, instead of on first sight with a cache miss or two per face.
      tableState_ = TableState::MeshFaces;
      meshColors_.resize(meshFaces);
      for (uint32_t f = 0; f < meshFaces; ++f) meshColors_[f] = normalColor(modelView_[0], f);
      return;
    }
    if (tableState_ == TableState::Off) return;
    // Entry 0 is the background, entry id + 1 face id's color, so that the look-up of
    // uint32_t(key) + 1 needs no branch (the background id wraps to 0).
    colorTable_.resize(size_t(scene_.faceCount()) + 1);
    colorTable_[0] = background_;
    if (!geometry_) {
      for (uint32_t id = 0; id < scene_.faceCount(); ++id)
        colorTable_[size_t(id) + 1] = faceColor(id);
      return;
    }
  }
  if (tableState_ != TableState::On || !geometry_) return;
  // Each face of the frame comes once: no per-face cache to ask. The octree's faces come in
  // its leaf order, unrelated to their ids, so the normals and table entries they need are
  // fetched a few faces ahead (bunny, octree raster 9.30 -> 8.44 ms in alternated runs, from
  // cache misses here; 32 ahead measured a little better than 8 and 16).
  constexpr size_t kAhead = 32;
  const std::vector<ScreenFace>& faces = geometry_->faces;
  const uint32_t nf = uint32_t(scene_.mesh->faceCount());
  for (; tableFaces_ < faces.size(); ++tableFaces_) {
    if (tableFaces_ + kAhead < faces.size()) {
      const uint32_t ahead = faces[tableFaces_ + kAhead].id;
      __builtin_prefetch(&faceNormals_[ahead % nf]);
      __builtin_prefetch(&colorTable_[size_t(ahead) + 1], 1);
    }
    colorTable_[size_t(faces[tableFaces_].id) + 1] = uncachedFaceColor(faces[tableFaces_].id);
  }
}

void Shader::rowsFinal(int sampleRows) {
  // Depth mode stretches over the depths of the whole frame: it waits for finish().
  if (mode_ == ShadingMode::Depth) return;
  shadePixelRows(std::min(sampleRows / scale_, color_->rows));
}

void Shader::finish() {
  if (mode_ == ShadingMode::Depth) {
    depthLo_ = 1.0f;
    float depthHi = 0.0f;
    for (size_t i = 0; i < fb_->size(); ++i) {
      if (keyFaceId(fb_->data()[i]) == kBackgroundId) continue;
      const float d = keyDepth(fb_->data()[i]);
      depthLo_ = std::min(depthLo_, d);
      depthHi = std::max(depthHi, d);
    }
    depthRange_ = depthHi > depthLo_ ? double(depthHi) - depthLo_ : 1.0;
  }
  shadePixelRows(color_->rows);
}

void Shader::shade(const FrameBuffer& fb, const Camera& camera, int scale, cv::Mat& color) {
  begin(fb, camera, scale, color);
  finish();
}

uint32_t Shader::sampleColor(DepthKey key, int x, int y) {
  const uint32_t id = keyFaceId(key);
  if (id == kBackgroundId) return background_;
  if (mode_ == ShadingMode::Depth) {
    // Near white, far black, stretched over the depths present in the frame.
    const double g = 1.0 - (double(keyDepth(key)) - depthLo_) / depthRange_;
    return packRgb(g, g, g);
  }
  if (!perSample_) return faceColor(id);
  const Vec3 dir(rayOriginX_ + (x + 0.5) * rayScaleX_, rayOriginY_ - (y + 0.5) * rayScaleY_, -1.0);
  const cv::Vec3b c = shadeSample(id, dir);
  return (uint32_t(c[2]) << 16) | (uint32_t(c[1]) << 8) | c[0];
}

void Shader::shadePixelRows(int endRow) {
  const int firstRow = shadedRows_;
  if (endRow <= firstRow) return;
  shadedRows_ = endRow;
  const FrameBuffer& fb = *fb_;
  cv::Mat& color = *color_;
  prepareTable();
  if (tableState_ == TableState::On) {
    const uint32_t* table = colorTable_.data();
    shadeRows(fb, firstRow, endRow, background_, color,
              [table](DepthKey key) { return table[uint32_t(keyFaceId(key) + 1u)]; });
    return;
  }
  if (tableState_ == TableState::MeshFaces) {
    const uint32_t* table = meshColors_.data();
    const uint32_t meshFaces = uint32_t(meshColors_.size());
    shadeFaceRuns(fb, firstRow, endRow, background_, color,
                  [&](uint32_t id) { return table[id % meshFaces]; });
    return;
  }
  if (perFace_) {
    shadeFaceRuns(fb, firstRow, endRow, background_, color,
                  [&](uint32_t id) { return faceColor(id); });
    return;
  }

  const int width = color.cols;
  for (int y = firstRow; y < endRow; ++y) {
    uchar* out = color.ptr<uchar>(y);
    if (scale_ == 1) {
      const DepthKey* row = fb.row(y);
      for (int x = 0; x < width; ++x) {
        const uint32_t c = sampleColor(row[x], x, y);
        out[3 * x + 0] = uchar(c);
        out[3 * x + 1] = uchar(c >> 8);
        out[3 * x + 2] = uchar(c >> 16);
      }
    } else if (mode_ == ShadingMode::Id) {
      // A mean of ids is no face's id: an id image holds each pixel's nearest sample, as
      // --ids does (SPEC §6 over the MSAA mean of §5).
      const DepthKey* r0 = fb.row(2 * y);
      const DepthKey* r1 = fb.row(2 * y + 1);
      for (int x = 0; x < width; ++x) {
        const uint32_t c = sampleColor(
            std::min({r0[2 * x], r0[2 * x + 1], r1[2 * x], r1[2 * x + 1]}), 2 * x, 2 * y);
        out[3 * x + 0] = uchar(c);
        out[3 * x + 1] = uchar(c >> 8);
        out[3 * x + 2] = uchar(c >> 16);
      }
    } else {
      const DepthKey* r0 = fb.row(2 * y);
      const DepthKey* r1 = fb.row(2 * y + 1);
      for (int x = 0; x < width; ++x) {
        uint32_t sum[3] = {0, 0, 0};
        const uint32_t cs[4] = {sampleColor(r0[2 * x], 2 * x, 2 * y),
                                sampleColor(r0[2 * x + 1], 2 * x + 1, 2 * y),
                                sampleColor(r1[2 * x], 2 * x, 2 * y + 1),
                                sampleColor(r1[2 * x + 1], 2 * x + 1, 2 * y + 1)};
        for (uint32_t c : cs) {
          sum[0] += c & 0xFF;
          sum[1] += (c >> 8) & 0xFF;
          sum[2] += (c >> 16) & 0xFF;
        }
        // The rounded mean of the four samples, background included (SPEC §5).
        for (int i = 0; i < 3; ++i) out[3 * x + i] = uchar((sum[i] + 2) / 4);
      }
    }
  }
}

}  // namespace zrender
