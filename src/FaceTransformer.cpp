#include "zrender/FaceTransformer.hpp"

#include <algorithm>
#include <cmath>

#include "zrender/Clipping.hpp"
#include "zrender/Triangulation.hpp"

namespace zrender {

FaceTransformer::FaceTransformer(const Scene& scene, const Camera& camera, int sampleScale,
                                 bool cull)
    : scene_(scene), camera_(camera), scale_(sampleScale), cull_(cull) {
  const Mat4 viewProjection = camera.projection * camera.view;
  for (uint32_t k = 0; k < scene.instanceCount(); ++k)
    mvp_.push_back(viewProjection * scene.modelMatrix(k));
}

void FaceTransformer::transformAll(FrameGeometry& out) {
  const Mesh& mesh = *scene_.mesh;
  const size_t nv = mesh.positions.size();
  clip_.resize(nv * scene_.instanceCount());
  for (uint32_t k = 0; k < scene_.instanceCount(); ++k) {
    const Mat4& m = mvp_[k];
    Vec4* dst = clip_.data() + size_t(k) * nv;
    for (size_t v = 0; v < nv; ++v) {
      const Vec3& p = mesh.positions[v];
      dst[v] = m * Vec4(p[0], p[1], p[2], 1.0);
    }
  }
  out.width = camera_.width * scale_;
  out.height = camera_.height * scale_;
  const uint32_t nf = uint32_t(mesh.faceCount());
  for (uint32_t k = 0; k < scene_.instanceCount(); ++k) {
    const Vec4* base = clip_.data() + size_t(k) * nv;
    for (uint32_t f = 0; f < nf; ++f) {
      const uint32_t n = mesh.cornerCount(f);
      const Corner* c = mesh.faceCorners(f);
      faceClip_.resize(n);
      for (uint32_t i = 0; i < n; ++i) faceClip_[i] = base[c[i].position];
      appendFace(k * nf + f, faceClip_.data(), n, out);
    }
  }
}

const Vec4& FaceTransformer::lazyClipVertex(uint32_t instance, int32_t vertex) {
  const size_t nv = scene_.mesh->positions.size();
  if (clip_.size() != nv * scene_.instanceCount()) {
    clip_.resize(nv * scene_.instanceCount());
    clipReady_.assign(clip_.size(), 0);
  }
  const size_t i = size_t(instance) * nv + size_t(vertex);
  if (!clipReady_[i]) {
    const Vec3& p = scene_.mesh->positions[size_t(vertex)];
    clip_[i] = mvp_[instance] * Vec4(p[0], p[1], p[2], 1.0);
    clipReady_[i] = 1;
  }
  return clip_[i];
}

void FaceTransformer::transformFace(uint32_t faceId, FrameGeometry& out) {
  const Mesh& mesh = *scene_.mesh;
  const uint32_t nf = uint32_t(mesh.faceCount());
  const uint32_t k = faceId / nf, f = faceId % nf;
  out.width = camera_.width * scale_;
  out.height = camera_.height * scale_;
  const uint32_t n = mesh.cornerCount(f);
  const Corner* c = mesh.faceCorners(f);
  faceClip_.resize(n);
  for (uint32_t i = 0; i < n; ++i) faceClip_[i] = lazyClipVertex(k, c[i].position);
  appendFace(faceId, faceClip_.data(), n, out);
}

void FaceTransformer::appendFace(uint32_t faceId, const Vec4* clip, uint32_t n,
                                 FrameGeometry& out) {
  TransformCounters& counters = out.counters;
  const uint64_t pieces = n >= 3 ? n - 2 : 1;
  if (n < 3) {
    counters.degenerate += pieces;
    return;
  }
  // Outcodes: a face wholly beyond one plane of the view volume covers nothing.
  unsigned all = 0x3F, any = 0;
  for (uint32_t i = 0; i < n; ++i) {
    const Vec4& p = clip[i];
    if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]) &&
          std::isfinite(p[3]))) {
      counters.degenerate += pieces;
      return;
    }
    const unsigned code = (p[0] < -p[3]) | (p[0] > p[3]) << 1 | (p[1] < -p[3]) << 2 |
                          (p[1] > p[3]) << 3 | (p[2] < -p[3]) << 4 | (p[2] > p[3]) << 5;
    all &= code;
    any |= code;
  }
  if (all) {
    counters.clippedAway += pieces;
    return;
  }
  const Vec4* poly = clip;
  uint32_t count = n;
  if (any & 0x30) {
    clipped_.resize(n + 2);
    clipScratch_.resize(n + 2);
    count = uint32_t(clipNearFar(clip, n, clipped_.data(), clipScratch_.data()));
    if (count == 0) {
      counters.clippedAway += pieces;
      return;
    }
    poly = clipped_.data();
  }

  // Window coordinates in pixels (x right, y down, z depth 0..1).
  window_.resize(count);
  for (uint32_t i = 0; i < count; ++i)
    window_[i] = clipToWindow(poly[i], camera_.width, camera_.height);

  // Depth plane z = a x + b y + c in sample coordinates, from the unsnapped positions.
  Vec3 normal(0, 0, 0), centre(0, 0, 0);
  for (uint32_t i = 0; i < count; ++i) {
    const Vec3 p = Vec3(window_[i][0] * scale_, window_[i][1] * scale_, window_[i][2]);
    const Vec3& qw = window_[(i + 1) % count];
    const Vec3 q = Vec3(qw[0] * scale_, qw[1] * scale_, qw[2]);
    normal += Vec3((p[1] - q[1]) * (p[2] + q[2]), (p[2] - q[2]) * (p[0] + q[0]),
                   (p[0] - q[0]) * (p[1] + q[1]));
    centre += p;
  }
  centre *= 1.0 / count;
  if (normal[2] == 0.0 || !std::isfinite(normal[2])) {
    counters.degenerate += pieces;
    return;
  }
  DepthPlane plane;
  plane.a = -normal[0] / normal[2];
  plane.b = -normal[1] / normal[2];
  plane.c = centre[2] - plane.a * centre[0] - plane.b * centre[1];

  // Keep snapped coordinates in range however far outside the image the face reaches.
  const double guard = kGuardBand / scale_;
  const Vec3* win = window_.data();
  bool outside = false;
  for (uint32_t i = 0; i < count; ++i)
    outside |= std::abs(win[i][0]) > guard || std::abs(win[i][1]) > guard;
  if (outside) {
    guarded_.resize(count + 4);
    guardScratch_.resize(count + 4);
    count = uint32_t(clipGuardBand(win, count, guard, guarded_.data(), guardScratch_.data()));
    if (count == 0) {
      counters.clippedAway += pieces;
      return;
    }
    win = guarded_.data();
  }

  // Snap to 1/256 pixel, then scale to samples; drop repeated corners.
  snapped_.clear();
  for (uint32_t i = 0; i < count; ++i) {
    const FixedPoint p{snapToSubpixel(win[i][0]) * scale_, snapToSubpixel(win[i][1]) * scale_};
    if (snapped_.empty() || p != snapped_.back()) snapped_.push_back(p);
  }
  while (snapped_.size() > 1 && snapped_.back() == snapped_.front()) snapped_.pop_back();
  if (snapped_.size() < 3) {
    counters.degenerate += pieces;
    return;
  }
  __int128 area = 0;
  for (size_t i = 0; i < snapped_.size(); ++i) {
    const FixedPoint& a = snapped_[i];
    const FixedPoint& b = snapped_[(i + 1) % snapped_.size()];
    area += __int128(int64_t(a.x) * b.y - int64_t(b.x) * a.y);
  }
  if (area == 0) {
    counters.degenerate += pieces;
    return;
  }
  // y points down in window space, so counter-clockwise in NDC is a negative area here.
  const bool frontFacing = area < 0;
  if (cull_ && !frontFacing) {
    counters.backfaceCulled += pieces;
    return;
  }
  pieces_.clear();
  if (!triangulatePolygon(snapped_.data(), uint32_t(snapped_.size()), pieces_, ring_) ||
      pieces_.empty()) {
    counters.degenerate += pieces;
    return;
  }

  ScreenFace face;
  face.id = faceId;
  face.firstVertex = uint32_t(out.vertices.size());
  face.vertexCount = uint32_t(snapped_.size());
  face.firstTriangle = uint32_t(out.triangles.size());
  face.triangleCount = uint32_t(pieces_.size());
  face.plane = plane;
  face.frontFacing = frontFacing;
  const uint32_t faceIndex = uint32_t(out.faces.size());
  out.vertices.insert(out.vertices.end(), snapped_.begin(), snapped_.end());
  for (const auto& t : pieces_)
    out.triangles.push_back(
        ScreenTriangle{{snapped_[t[0]], snapped_[t[1]], snapped_[t[2]]}, faceIndex, faceId, plane});
  out.faces.push_back(face);
}

}  // namespace zrender
