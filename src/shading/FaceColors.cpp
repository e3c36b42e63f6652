#include "zrender/shading/FaceColors.hpp"

#include <algorithm>
#include <cmath>

#include "zrender/shading/ShadingModel.hpp"

namespace zrender {

FaceColors::FaceColors(const Scene& scene, ShadingMode mode) : scene_(scene), mode_(mode) {
  const Mesh& mesh = *scene.mesh;
  faceNormals_.resize(mesh.faceCount());
  for (size_t f = 0; f < mesh.faceCount(); ++f) faceNormals_[f] = newellNormal(mesh, f);
}

void FaceColors::begin(const std::vector<Mat4>& modelView, uint32_t background,
                       const FaceParts& faces) {
  modelView_ = &modelView;
  background_ = background;
  faces_ = faces;
  if (cache_.size() != scene_.faceCount()) {
    cache_.assign(scene_.faceCount(), Cached());
    frame_ = 0;
  }
  ++frame_;
  // Only where every instance is the whole mesh can a mesh face's color serve every instance.
  sharedRotation_ = scene_.uniform;
  for (const Mat4& mv : modelView)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        sharedRotation_ = sharedRotation_ && mv(i, j) == modelView[0](i, j);
  decided_ = false;
  tableFaces_ = 0;
}

uint32_t FaceColors::normalColor(const Mat4& modelView, uint32_t local) const {
  // Rigid transform of a unit (or zero) normal: no renormalization needed.
  const Vec3 n = transformDirection(modelView, faceNormals_[local]);
  return packRgb((n[0] + 1) * 0.5, (n[1] + 1) * 0.5, (n[2] + 1) * 0.5);
}

uint32_t FaceColors::color(uint32_t faceId) {
  // Colors of the id alone: a few operations, cheaper than a look-up in a table of every face.
  if (mode_ == ShadingMode::Id || mode_ == ShadingMode::Random) return uncachedColor(faceId);
  const uint32_t nf = uint32_t(scene_.mesh->faceCount());
  // Normal colors of instances that share their rotation are those of the mesh face: one
  // entry per mesh face, which stays in cache where one per face of a big grid does not.
  Cached& entry = cache_[mode_ == ShadingMode::Normal && sharedRotation_ ? faceId % nf : faceId];
  if (entry.stamp == frame_) return entry.color;
  entry.stamp = frame_;
  entry.color = uncachedColor(faceId);
  return entry.color;
}

uint32_t FaceColors::uncachedColor(uint32_t faceId) const {
  if (mode_ == ShadingMode::Id) return idColor(faceId);
  if (mode_ == ShadingMode::Random) return randomFaceColor(faceId);
  const FaceRef face = scene_.locate(faceId);
  const uint32_t local = face.meshFace;
  const Mat4& modelView = (*modelView_)[face.instance];
  if (mode_ == ShadingMode::Normal) return normalColor(modelView, local);
  if (mode_ != ShadingMode::Flat) return 0;
  // Lambert term of the face normal under a light at the eye, seen from the centroid.
  const Mesh& mesh = *scene_.mesh;
  const Corner* c = mesh.faceCorners(local);
  const uint32_t n = mesh.cornerCount(local);
  Vec3 centroid(0, 0, 0);
  for (uint32_t i = 0; i < n; ++i) centroid += mesh.positions[size_t(c[i].position)];
  centroid *= 1.0 / std::max<uint32_t>(n, 1);
  const Vec3 p = transformPoint(modelView, centroid);
  const Vec3 normal = transformDirection(modelView, faceNormals_[local]);
  const double g = std::abs(normal.dot(safeNormalize(-p)));
  return packRgb(g, g, g);
}

FaceColors::Lookup FaceColors::prepare(size_t samples, const Threads* threads) {
  // The common case (one color per face and pixel) is a table look-up per pixel, when there
  // are few faces for the pixels (the bunny: 31k front faces, 3.2M pixels): computing the
  // colors of the frame's faces in a row is cheaper than computing them on first sight, where
  // each look-up of the face's normal is a cache miss. Only faces of the frame's geometry can
  // be in the buffer, so only theirs are computed, as they appear.
  if (!decided_) {
    decided_ = true;
    const size_t faces = faces_.empty() ? size_t(scene_.faceCount()) : totalFaces(faces_);
    lookup_ = faces * 16 <= samples ? Lookup::ById : Lookup::OnSight;
    const uint32_t meshFaces = uint32_t(scene_.mesh->faceCount());
    if (lookup_ == Lookup::OnSight && mode_ == ShadingMode::Normal && sharedRotation_ &&
        size_t(meshFaces) * 16 <= samples) {
      // Many faces of a grid (the crowd: 475k transformed, 69k per bunny): normal colors are
      // those of the mesh faces, all computed in a row (normals read in order) into a table
      // that stays in cache, instead of on first sight with a cache miss or two per face.
      lookup_ = Lookup::ByMeshFace;
      table_.resize(meshFaces);
      for (uint32_t f = 0; f < meshFaces; ++f) table_[f] = normalColor((*modelView_)[0], f);
      return lookup_;
    }
    if (lookup_ == Lookup::OnSight) return lookup_;
    // Entry 0 is the background, entry id + 1 face id's color, so that the look-up of
    // uint32_t(key) + 1 needs no branch (the background id wraps to 0).
    table_.resize(size_t(scene_.faceCount()) + 1);
    table_[0] = background_;
    if (faces_.empty()) {
      if (threads && threads->parallel()) {
        threads->forRanges(scene_.faceCount(), 4096, [&](size_t begin, size_t end) {
          for (size_t id = begin; id < end; ++id) table_[id + 1] = uncachedColor(uint32_t(id));
        });
        return lookup_;
      }
      for (uint32_t id = 0; id < scene_.faceCount(); ++id) table_[size_t(id) + 1] = color(id);
      return lookup_;
    }
  }
  if (lookup_ != Lookup::ById || faces_.empty()) return lookup_;
  if (faces_.size() > 1) {
    // Parts come whole, once per frame: each part a task (the threads write distinct entries).
    const size_t total = totalFaces(faces_);
    if (tableFaces_ == total) return lookup_;
    const auto part = [&](size_t p) {
      for (const ScreenFace& face : faces_[p]->faces)
        table_[size_t(face.id) + 1] = uncachedColor(face.id);
    };
    if (threads && threads->parallel())
      threads->forEach(faces_.size(), part);
    else
      for (size_t p = 0; p < faces_.size(); ++p) part(p);
    tableFaces_ = total;
    return lookup_;
  }
  // One geometry, which may have grown since the last call (an algorithm of one thread).
  const GeometryVector<ScreenFace>& faces = faces_[0]->faces;
  if (threads && threads->parallel()) {
    // Each face once: the threads write distinct entries.
    threads->forRanges(faces.size() - tableFaces_, 4096, [&](size_t begin, size_t end) {
      for (size_t i = tableFaces_ + begin; i < tableFaces_ + end; ++i)
        table_[size_t(faces[i].id) + 1] = uncachedColor(faces[i].id);
    });
    tableFaces_ = faces.size();
    return lookup_;
  }
  // Each face of the frame comes once: no per-face cache to ask. The octree's faces come in
  // its leaf order, unrelated to their ids, so the normals and table entries they need are
  // fetched a few faces ahead (32 ahead measured a little better than 8 and 16).
  constexpr size_t kAhead = 32;
  for (; tableFaces_ < faces.size(); ++tableFaces_) {
    if (tableFaces_ + kAhead < faces.size()) {
      const uint32_t ahead = faces[tableFaces_ + kAhead].id;
      __builtin_prefetch(&faceNormals_[scene_.locate(ahead).meshFace]);
      __builtin_prefetch(&table_[size_t(ahead) + 1], 1);
    }
    table_[size_t(faces[tableFaces_].id) + 1] = uncachedColor(faces[tableFaces_].id);
  }
  return lookup_;
}

}  // namespace zrender
