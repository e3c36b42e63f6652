#include "zrender/shading/SurfaceSetup.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>

#include "zrender/base/CpuFeatures.hpp"
#include "zrender/base/Prefetch.hpp"
#include "zrender/shading/ShadingModel.hpp"

namespace zrender {

SurfaceSetup::SurfaceSetup(const Scene& scene, ShadingMode mode) : scene_(scene), mode_(mode) {
  const Mesh& mesh = *scene.mesh;
  std::vector<Vec3> faceNormals(mesh.faceCount());
  for (size_t f = 0; f < mesh.faceCount(); ++f) faceNormals[f] = newellNormal(mesh, f);
  std::vector<Vec3> smoothNormals;  // per position, when the model has no vn
  if ((mode == ShadingMode::Phong || mode == ShadingMode::Texture) && !mesh.hasNormals()) {
    // Smooth normals: area-weighted sum of the normals of the faces around each position.
    smoothNormals.assign(mesh.positions.size(), Vec3(0, 0, 0));
    for (size_t f = 0; f < mesh.faceCount(); ++f) {
      const Vec3 weighted = newellSum(mesh, f);
      const Corner* c = mesh.faceCorners(f);
      for (uint32_t i = 0; i < mesh.cornerCount(f); ++i)
        smoothNormals[size_t(c[i].position)] += weighted;
    }
    for (Vec3& n : smoothNormals) n = safeNormalize(n);
  }
  // Each distinct texture framed once (FaceSurface); faces point at theirs.
  std::vector<const cv::Mat*> distinct;
  const auto indexOf = [&](const cv::Mat& t) -> int32_t {
    if (mode != ShadingMode::Texture || t.empty()) return -1;
    for (size_t i = 0; i < distinct.size(); ++i) {
      if (distinct[i]->data == t.data) return int32_t(i);
    }
    distinct.push_back(&t);
    return int32_t(distinct.size() - 1);
  };
  triangles_ = true;
  for (size_t f = 0; f < mesh.faceCount(); ++f) triangles_ = triangles_ && mesh.cornerCount(f) == 3;
  corners_.resize(mesh.corners.size());
  faces_.resize(mesh.faceCount());
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const Corner* c = mesh.faceCorners(f);
    const uint32_t n = mesh.cornerCount(f);
    bool allNormals = mesh.hasNormals(), allUvs = mesh.hasTexcoords();
    for (uint32_t i = 0; i < n; ++i) {
      allNormals &= c[i].normal >= 0;
      allUvs &= c[i].texcoord >= 0;
    }
    for (uint32_t i = 0; i < n; ++i) {
      CornerData& d = corners_[mesh.faceStart[f] + i];
      d.position = mesh.positions[size_t(c[i].position)];
      const Vec3& normal = allNormals               ? mesh.normals[size_t(c[i].normal)]
                           : !smoothNormals.empty() ? smoothNormals[size_t(c[i].position)]
                                                    : faceNormals[f];
      d.normal = cv::Vec3f(normal);
      d.uv = allUvs ? cv::Vec2f(mesh.texcoords[size_t(c[i].texcoord)]) : cv::Vec2f(0, 0);
    }
    FaceData& face = faces_[f];
    face.geometric = cv::Vec3f(faceNormals[f]);
    const int32_t material = f < mesh.faceMaterial.size() ? mesh.faceMaterial[f] : -1;
    face.base = f < mesh.faceColors.size() ? mesh.faceColors[f]
                : material >= 0            ? mesh.materials[size_t(material)].diffuse
                                           : cv::Vec3f(0.8f, 0.8f, 0.8f);
    face.allUvs = allUvs;
    face.texture = allUvs ? indexOf(scene.textureOf(uint32_t(f))) : -1;
  }
  // Objects' own textures: for each instance that has one, its index among textures_.
  for (const SceneInstance& instance : scene.instances)
    instanceTextures_.push_back(instance.texture >= 0 && scene.texture.empty()
                                    ? indexOf(scene.objectTextures[size_t(instance.texture)])
                                    : -1);
  textures_.resize(distinct.size());
  for (size_t i = 0; i < distinct.size(); ++i) {
    // Framed by a copy of the last column and row before the first and of the first after the
    // last (SurfaceTexture), so that bilinear filtering reads texel pairs without wrapping.
    const cv::Mat& t = *distinct[i];
    const int rows = t.rows, cols = t.cols;
    const int stride = cols + 2;
    Texture& out = textures_[i];
    out.width = cols;
    out.height = rows;
    out.texels.resize(size_t(stride) * size_t(rows + 2));  // every texel written below
    const auto texel = [](const uint8_t* bgr) {
      return uint32_t(bgr[2]) << 16 | uint32_t(bgr[1]) << 8 | bgr[0];
    };
    for (int y = 0; y < rows + 2; ++y) {
      const uint8_t* row = t.ptr((y + rows - 1) % rows);
      uint32_t* line = out.texels.data() + size_t(y) * size_t(stride);
      line[0] = texel(row + 3 * (cols - 1));
      for (int x = 0; x < cols; ++x) line[x + 1] = texel(row + 3 * x);
      line[cols + 1] = texel(row);
    }
    textureViews_.push_back(SurfaceTexture{out.texels.data(), cols, rows});
  }
  frame_.mode = mode;
}

void SurfaceSetup::begin(const std::vector<Mat4>& modelView, const Camera& camera, int widthSamples,
                         int heightSamples) {
  modelView_ = &modelView;
  width_ = widthSamples;
  height_ = heightSamples;
  if (cache_.size() != scene_.faceCount()) {
    cache_.assign(scene_.faceCount(), Cached());
    stamp_ = 0;
  }
  ++stamp_;
  batchDone_ = false;
  batched_ = false;
  byRows_ = false;
  records_.clear();
  fans_.clear();
  // The view-space ray through a sample centre: x_view / -z_view = x_ndc / P00.
  rayScaleX_ = 2.0 / widthSamples / camera.projection(0, 0);
  rayScaleY_ = 2.0 / heightSamples / camera.projection(1, 1);
  rayOriginX_ = -1.0 / camera.projection(0, 0);
  rayOriginY_ = 1.0 / camera.projection(1, 1);
  // At sample centres, as SurfaceFrame has it.
  frame_.rayOriginX = float(rayOriginX_ + 0.5 * rayScaleX_);
  frame_.rayOriginY = float(rayOriginY_ - 0.5 * rayScaleY_);
  frame_.rayScaleX = float(rayScaleX_);
  frame_.rayScaleY = float(rayScaleY_);
  frame_.textures = textureViews_.data();
}

bool SurfaceSetup::setUpFaces(const FaceParts& parts, size_t samples, const Threads* threads) {
  if (batchDone_) return batched_;
  batchDone_ = true;
  if (totalFaces(parts) * 16 > samples) return false;
  batched_ = true;
  byRows_ = true;
  // In order of their first row, so that the surfaces lie in memory about as the rows meet
  // them: a face met in a row follows, a few hundred bytes on, those met in the rows above,
  // instead of a cache miss each (a counting sort by row).
  std::vector<uint32_t>& start = rowStart_;
  start.assign(size_t(height_) + 1, 0);
  const auto rowOf = [&](const ScreenFace& face) {
    return std::min<size_t>(face.rows.first, size_t(height_ - 1));
  };
  for (const FrameGeometry* part : parts)
    for (const ScreenFace& face : part->faces) ++start[rowOf(face) + 1];
  for (size_t y = 1; y < start.size(); ++y) start[y] += start[y - 1];
  std::vector<uint32_t>& order = rowOrder_;
  order.resize(start.back());
  for (const FrameGeometry* part : parts)
    for (const ScreenFace& face : part->faces) order[start[rowOf(face)]++] = face.id;
  // Face order[i] gets record firstRecord + i and a polygon its fans from firstFan_[i] on: set up
  // side by side on the threads, each writing only its own.
  const Mesh& mesh = *scene_.mesh;
  const size_t firstRecord = records_.size();
  batchFirstRecord_ = firstRecord;
  records_.resize(firstRecord + order.size());
  std::vector<uint32_t>& firstFan = firstFan_;
  firstFan.resize(order.size());
  size_t fans = fans_.size();
  for (size_t i = 0; i < order.size(); ++i) {
    cache_[order[i]] = Cached{stamp_, uint32_t(firstRecord + i)};
    firstFan[i] = uint32_t(fans);
    if (triangles_) continue;
    const uint32_t count = fanCount(mesh.cornerCount(scene_.locate(order[i]).meshFace));
    if (count > 1) fans += count;
  }
  fans_.resize(fans);
  const bool fourAtOnce = triangles_ && cpuHasAvx2();
  const auto setUpRange = [&](size_t begin, size_t end) {
    constexpr size_t kAhead = 8;
    const auto prefetch = [&](uint32_t faceId) {
      const uint32_t local = scene_.locate(faceId).meshFace;
      prefetchLine(&faces_[local]);
      // A triangle's corners without a look at faceStart, itself a cache miss.
      const size_t cornerBegin = triangles_ ? 3 * size_t(local) : mesh.faceStart[local];
      const size_t cornerEnd = triangles_ ? cornerBegin + 3 : mesh.faceStart[local + 1];
      const char* first = reinterpret_cast<const char*>(corners_.data() + cornerBegin);
      const char* last = reinterpret_cast<const char*>(corners_.data() + cornerEnd);
      for (const char* p = first; p < last; p += 64) prefetchLine(p);
    };
    // The records are fetched a few faces ahead too: each line of them is read before it is
    // written, and the records of the last frame are long out of cache.
    for (size_t i = begin; i < std::min(begin + kAhead, end); ++i) prefetch(order[i]);
    size_t i = begin;
    // Four at a time where they are triangles and the CPU has AVX2.
    for (; fourAtOnce && i + 4 <= end; i += 4) {
      const size_t aheadEnd = std::min(i + kAhead + 4, end);
      for (size_t k = i + kAhead; k < aheadEnd; ++k) prefetch(order[k]);
      if (i + kAhead < end) prefetchRecords(i + kAhead, aheadEnd);
      SurfaceRecord* const records[4] = {&records_[firstRecord + i], &records_[firstRecord + i + 1],
                                         &records_[firstRecord + i + 2],
                                         &records_[firstRecord + i + 3]};
      setUpFourTriangles(&order[i], records, &firstFan[i]);
    }
    Scratch scratch;
    for (; i < end; ++i) {
      if (i + kAhead < end) {
        prefetch(order[i + kAhead]);
        prefetchRecords(i + kAhead, i + kAhead + 1);
      }
      setUpInto(scene_.locate(order[i]), records_[firstRecord + i], fans_.data() + firstFan[i],
                firstFan[i], scratch);
    }
  };
  if (threads && threads->parallel())
    threads->forRanges(order.size(), 256, setUpRange);
  else
    setUpRange(0, order.size());
  return true;
}

bool SurfaceSetup::setUpAll(size_t samples) {
  if (batchDone_) return batched_;
  batchDone_ = true;
  const uint32_t n = scene_.faceCount();
  if (size_t(n) * 16 > samples) return false;
  batched_ = true;
  for (uint32_t id = 0; id < n; ++id) surface(id);  // in order: no need to fetch ahead
  return true;
}

void SurfaceSetup::setUpVisible(const FrameBuffer& fb, const FaceParts& faces,
                                const Threads& threads) {
  if (!faces.empty() && setUpFaces(faces, fb.size())) return;
  // The faces in the buffer, each listed once by the thread that marks it first (in no fixed
  // order: set-up order changes no color), then set up one after the other.
  std::vector<std::atomic<uint64_t>> seen((size_t(scene_.faceCount()) + 63) / 64);
  std::vector<uint32_t> visible;
  std::mutex visibleMutex;
  const size_t width = size_t(fb.width());
  threads.forRanges(size_t(fb.height()), 16, [&](size_t begin, size_t end) {
    std::vector<uint32_t> found;
    for (const DepthKey* key = fb.row(int(begin));
         key != fb.row(int(begin)) + (end - begin) * width; ++key) {
      const uint32_t id = keyFaceId(*key);
      if (id == kBackgroundId) continue;
      const uint64_t bit = uint64_t(1) << (id & 63);
      std::atomic<uint64_t>& word = seen[id >> 6];
      if (!(word.load(std::memory_order_relaxed) & bit) &&
          !(word.fetch_or(bit, std::memory_order_relaxed) & bit))
        found.push_back(id);
    }
    const std::lock_guard<std::mutex> lock(visibleMutex);
    visible.insert(visible.end(), found.begin(), found.end());
  });
  for (uint32_t id : visible) surface(id);
}

uint32_t SurfaceSetup::setUp(uint32_t faceId) {
  const FaceRef ref = scene_.locate(faceId);
  const uint32_t count = triangles_ ? 1 : fanCount(scene_.mesh->cornerCount(ref.meshFace));
  const size_t firstFan = fans_.size();
  if (count > 1) fans_.resize(firstFan + count);
  setUpInto(ref, records_.emplace_back(), fans_.data() + firstFan, uint32_t(firstFan), scratch_);
  return uint32_t(records_.size() - 1);
}

FaceSurface SurfaceSetup::faceFields(const FaceRef& ref) const {
  const SceneInstance& instance = scene_.instances[ref.instance];
  const FaceData& data = faces_[ref.meshFace];
  FaceSurface face;
  // An object's own color takes the place of its faces' (SceneObject::color).
  const cv::Vec3f& base = instance.colored ? instance.color : data.base;
  for (int i = 0; i < 3; ++i) face.base[i] = base[i] * 255.0f;
  const int32_t textureIndex = data.allUvs && instanceTextures_[ref.instance] >= 0
                                   ? instanceTextures_[ref.instance]
                                   : data.texture;
  face.texture = textureIndex;
  return face;
}

void SurfaceSetup::placeOrigin(FaceSurface& face, const Vec3& p0) const {
  // The sample of the first corner when it lies in front of the eye (clamped to the image),
  // else the image's centre. From the face alone, so that it is the same whichever sample
  // meets the face first.
  face.originX = width_ / 2;
  face.originY = height_ / 2;
  if (p0[2] < 0.0) {
    const double x = (p0[0] / -p0[2] - rayOriginX_) / rayScaleX_ - 0.5;
    const double y = (rayOriginY_ - p0[1] / -p0[2]) / rayScaleY_ - 0.5;
    if (std::isfinite(x) && std::isfinite(y)) {
      face.originX = int32_t(std::clamp(std::round(x), 0.0, width_ - 1.0));
      face.originY = int32_t(std::clamp(std::round(y), 0.0, height_ - 1.0));
    }
  }
}

void SurfaceSetup::setUpInto(const FaceRef& ref, SurfaceRecord& record, SurfaceFan* polygonFans,
                             uint32_t firstFan, Scratch& scratch) const {
  const Mesh& mesh = *scene_.mesh;
  const uint32_t local = ref.meshFace;
  const Mat4& mv = (*modelView_)[ref.instance];
  const uint32_t n = triangles_ ? 3 : mesh.cornerCount(local);
  const CornerData* corners =
      corners_.data() + (triangles_ ? 3 * size_t(local) : mesh.faceStart[local]);
  std::vector<Vec3>& cornerPosition = scratch.position;
  std::vector<Vec3>& cornerNormal = scratch.normal;
  cornerPosition.resize(n);
  cornerNormal.resize(n);
  for (uint32_t i = 0; i < n; ++i) {
    cornerPosition[i] = transformAffinePoint(mv, corners[i].position);
    cornerNormal[i] = safeNormalize(transformDirection(mv, Vec3(corners[i].normal)));
  }
  const Vec3& p0 = cornerPosition[0];

  FaceSurface face = faceFields(ref);
  // A back face seen (--no-cull) is lit from its own side: its normals turned to the eye.
  const bool flip = mode_ != ShadingMode::Normal &&
                    transformDirection(mv, Vec3(faces_[local].geometric)).dot(-p0) < 0.0;
  if (flip)
    for (Vec3& normal : cornerNormal) normal = -normal;
  placeOrigin(face, p0);
  // The ray through a sample is affine in its position, dir = (rayOriginX + (x + 0.5)
  // rayScaleX, rayOriginY - (y + 0.5) rayScaleY, -1), so for a fan triangle with edges e1, e2
  // from p0, the intersection's weights u = dir.(e2 x -p0) / dir.(e2 x e1) and v = dir.(-p0 x
  // e1) / dir.(e2 x e1) (Moeller and Trumbore's, rearranged) are ratios of affine functions of
  // the sample: three planes.
  const Vec3 origin(rayOriginX_ + (face.originX + 0.5) * rayScaleX_,
                    rayOriginY_ - (face.originY + 0.5) * rayScaleY_, -1.0);
  face.firstFan = firstFan;
  face.fanCount = fanCount(n);
  for (uint32_t j = 1; j + 1 < std::max<uint32_t>(n, 3); ++j) {
    SurfaceFan& fan = face.fanCount == 1 ? record.fan : polygonFans[j - 1];
    const uint32_t corner[3] = {0, std::min(j, n - 1), std::min(j + 1, n - 1)};
    const Vec3 e1 = cornerPosition[corner[1]] - p0, e2 = cornerPosition[corner[2]] - p0;
    const Vec3 toEye = -p0;
    const Vec3 vectors[3] = {e2.cross(e1), e2.cross(toEye), toEye.cross(e1)};
    fan.degenerate = vectors[0] == Vec3(0, 0, 0);
    double planes[8][3];  // a, b, c of den, pu, pv, then the normal's and uv's over den
    double largest = 0.0;
    for (int k = 0; k < 3; ++k) {
      planes[k][0] = vectors[k][0] * rayScaleX_;
      planes[k][1] = -vectors[k][1] * rayScaleY_;
      planes[k][2] = vectors[k].dot(origin);
      for (double value : planes[k]) largest = std::max(largest, std::abs(value));
    }
    // An attribute A over den: A0 den + (Aj - A0) pu + (Aj+1 - A0) pv, coefficient by
    // coefficient.
    double attribute[5][3];  // the normal's x, y, z and u, v at corners 0, j, j + 1
    for (int i = 0; i < 3; ++i) {
      for (int a = 0; a < 3; ++a) attribute[a][i] = cornerNormal[corner[i]][a];
      for (int a = 0; a < 2; ++a) attribute[3 + a][i] = corners[corner[i]].uv[a];
    }
    for (int k = 0; k < 5; ++k)
      for (int c = 0; c < 3; ++c)
        planes[3 + k][c] = attribute[k][0] * planes[0][c] +
                           (attribute[k][1] - attribute[k][0]) * planes[1][c] +
                           (attribute[k][2] - attribute[k][0]) * planes[2][c];
    // A common factor leaves the ratios as they are: one that keeps the floats in range, with
    // the sign that makes den positive where the ray meets the plane in front of the eye (the
    // ray t dir meets it where t = p0.(e2 x e1) / dir.(e2 x e1)).
    const double sign = p0.dot(vectors[0]) < 0.0 ? -1.0 : 1.0;
    const double scale = (largest > 0.0 && std::isfinite(largest) ? 1.0 / largest : 1.0) * sign;
    for (int k = 0; k < kSurfacePlanes; ++k) {  // planes[] is in SurfacePlane order
      fan.a[k] = float(planes[k][0] * scale);
      fan.b[k] = float(planes[k][1] * scale);
      fan.c[k] = float(planes[k][2] * scale);
    }
    for (int i = 0; i < 3; ++i) {
      for (int a = 0; a < 3; ++a) fan.cornerNormal[i][a] = float(attribute[a][i]);
      for (int a = 0; a < 2; ++a) fan.cornerUv[i][a] = float(attribute[3 + a][i]);
    }
  }
  record.face = face;
}

}  // namespace zrender
