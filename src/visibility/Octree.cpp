#include "zrender/visibility/Octree.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace zrender {

namespace {

// Spreads the low 10 bits of v to every third bit (bit i goes to bit 3 i).
uint32_t spreadBits(uint32_t v) {
  v &= 0x3FFu;
  v = (v | (v << 16)) & 0x030000FFu;
  v = (v | (v << 8)) & 0x0300F00Fu;
  v = (v | (v << 4)) & 0x030C30C3u;
  v = (v | (v << 2)) & 0x09249249u;
  return v;
}

// Stable LSD radix sort of `keys` on bits [32, 32 + bits) (the Morton code above the face id).
void radixSortByCode(std::vector<uint64_t>& keys, int bits) {
  constexpr int kDigitBits = 10;
  constexpr size_t kBuckets = size_t(1) << kDigitBits;
  std::vector<uint64_t> scratch(keys.size());
  std::vector<size_t> count(kBuckets);
  for (int shift = 32; shift < 32 + bits; shift += kDigitBits) {
    std::fill(count.begin(), count.end(), size_t(0));
    for (uint64_t k : keys) ++count[(k >> shift) & (kBuckets - 1)];
    size_t sum = 0;
    for (size_t& c : count) {
      const size_t n = c;
      c = sum;
      sum += n;
    }
    for (uint64_t k : keys) scratch[count[(k >> shift) & (kBuckets - 1)]++] = k;
    keys.swap(scratch);
  }
}

class Builder {
 public:
  Builder(const Scene& scene, uint32_t leafFaces, std::vector<OctreeNode>& nodes,
          std::vector<uint32_t>& faces)
      : scene_(scene),
        mesh_(*scene.mesh),
        leafFaces_(std::max(leafFaces, 1u)),
        nodes_(nodes),
        faces_(faces) {
    // A grid's instances differ by a translation only (Scene: the rotation, then the grid
    // offset), so the rotated positions are shared: world = rotated + offset, equal to the
    // transformer's model matrix product up to rounding, which the box margin covers. Objects
    // placed otherwise have each vertex through their own matrix.
    const Mat4& first = scene.modelMatrix(0);
    shared_ = scene.uniform;
    for (const SceneInstance& instance : scene.instances) {
      for (int r = 0; r < 3 && shared_; ++r)
        for (int c = 0; c < 3; ++c) shared_ &= instance.model(r, c) == first(r, c);
      offsets_.emplace_back(instance.model(0, 3), instance.model(1, 3), instance.model(2, 3));
    }
    if (shared_) {
      Mat4 rot = first;  // the shared rotation (and scale)
      rot(0, 3) = rot(1, 3) = rot(2, 3) = 0.0;
      rotated_.reserve(mesh_.positions.size());
      for (const Vec3& p : mesh_.positions) rotated_.push_back(transformPoint(rot, p));
    }
  }

  void build() {
    const uint32_t total = scene_.faceCount();
    if (total == 0) return;

    // Scene bounds, for the Morton grid.
    Vec3 lo, hi;
    if (shared_) {  // every instance is the rotated mesh plus its offset
      const Box3 mesh = boundingBox(rotated_), offsets = boundingBox(offsets_);
      lo = mesh.lo + offsets.lo, hi = mesh.hi + offsets.hi;
    } else {
      lo = Vec3(HUGE_VAL, HUGE_VAL, HUGE_VAL), hi = -lo;
      for (uint32_t k = 0; k < scene_.instanceCount(); ++k) {
        const SceneModel& m = scene_.modelOf(k);
        for (uint32_t p = m.positionBegin; p < m.positionEnd; ++p) {
          const Vec3 w = world(k, p);
          for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], w[a]), hi[a] = std::max(hi[a], w[a]);
        }
      }
    }
    double side = 0.0, magnitude = 0.0;
    for (int a = 0; a < 3; ++a) {
      side = std::max(side, hi[a] - lo[a]);
      magnitude = std::max({magnitude, std::abs(lo[a]), std::abs(hi[a])});
    }
    if (!(side > 0.0) || !std::isfinite(side)) side = 1.0;
    origin_ = lo;
    cellScale_ = double(1 << Octree::kMaxDepth) / side;
    side_ = side;
    // Float rounding of the bounds (relative 2^-24 of the coordinates) and of the world
    // positions; widen every box by far more than that.
    margin_ = float(1e-6 * (magnitude + side));

    // Morton code of every face's centroid, sorted with the face id as the tie-break.
    std::vector<uint64_t> keys(total);
    const double top = double((1 << Octree::kMaxDepth) - 1);
    for (uint32_t k = 0; k < scene_.instanceCount(); ++k) {
      const SceneModel& m = scene_.modelOf(k);
      for (uint32_t f = m.faceBegin; f < m.faceEnd; ++f) {
        const uint32_t id = scene_.instances[k].firstId + (f - m.faceBegin);
        const uint32_t n = mesh_.cornerCount(f);
        const Corner* c = mesh_.faceCorners(f);
        Vec3 centroid(0, 0, 0);
        if (shared_) {
          for (uint32_t i = 0; i < n; ++i) centroid += rotated_[size_t(c[i].position)];
          if (n > 0) centroid *= 1.0 / n;
          centroid += offsets_[k];
        } else {
          for (uint32_t i = 0; i < n; ++i) centroid += world(k, uint32_t(c[i].position));
          if (n > 0) centroid *= 1.0 / n;
        }
        uint32_t q[3];
        for (int a = 0; a < 3; ++a) {
          double cell = std::floor((centroid[a] - origin_[a]) * cellScale_);
          if (!(cell >= 0.0)) cell = 0.0;  // also NaN
          q[a] = uint32_t(std::min(cell, top));
        }
        const uint32_t code = spreadBits(q[0]) | spreadBits(q[1]) << 1 | spreadBits(q[2]) << 2;
        keys[id] = uint64_t(code) << 32 | id;
      }
    }
    radixSortByCode(keys, 3 * Octree::kMaxDepth);
    faces_.resize(total);
    for (uint32_t i = 0; i < total; ++i) faces_[i] = uint32_t(keys[i]);
    codes_.resize(total);
    for (uint32_t i = 0; i < total; ++i) codes_[i] = uint32_t(keys[i] >> 32);
    std::vector<uint64_t>().swap(keys);

    nodes_.clear();
    nodes_.reserve(size_t(total) / leafFaces_ * 2 + 16);
    nodes_.emplace_back();
    buildNode(0, 0, 0, total, 0, 0, 0);
    for (OctreeNode& node : nodes_) {
      for (int a = 0; a < 3; ++a) {
        node.lo[a] -= margin_;
        node.hi[a] += margin_;
      }
    }
    std::vector<uint32_t>().swap(codes_);
  }

 private:
  void buildNode(uint32_t index, int depth, uint32_t begin, uint32_t end, uint32_t cx, uint32_t cy,
                 uint32_t cz) {
    {
      OctreeNode& node = nodes_[index];
      node.faceBegin = begin;
      node.faceEnd = end;
      node.childMask = 0;
      node.firstChild = 0;
      const double cellSide = side_ / double(1u << depth);
      const uint32_t cell[3] = {cx, cy, cz};
      for (int a = 0; a < 3; ++a) node.split[a] = float(origin_[a] + (cell[a] + 0.5) * cellSide);
    }
    if (end - begin <= leafFaces_ || depth == Octree::kMaxDepth) {
      leafBounds(index);
      return;
    }
    // The faces are sorted by code, so the octants at this depth are consecutive ranges.
    const int shift = 3 * (Octree::kMaxDepth - 1 - depth);
    uint32_t bounds[9];
    bounds[0] = begin;
    for (uint32_t o = 0; o < 8; ++o) {
      const uint32_t* first = codes_.data() + bounds[o];
      const uint32_t* last = codes_.data() + end;
      bounds[o + 1] = uint32_t(
          std::partition_point(first, last, [&](uint32_t c) { return ((c >> shift) & 7u) <= o; }) -
          codes_.data());
    }
    uint8_t mask = 0;
    for (uint32_t o = 0; o < 8; ++o)
      if (bounds[o + 1] > bounds[o]) mask |= uint8_t(1u << o);
    const uint32_t first = uint32_t(nodes_.size());
    nodes_.resize(nodes_.size() + size_t(__builtin_popcount(mask)));
    nodes_[index].childMask = mask;
    nodes_[index].firstChild = first;
    uint32_t child = first;
    for (uint32_t o = 0; o < 8; ++o) {
      if (!(mask & (1u << o))) continue;
      buildNode(child++, depth + 1, bounds[o], bounds[o + 1], 2 * cx + (o & 1),
                2 * cy + ((o >> 1) & 1), 2 * cz + ((o >> 2) & 1));
    }
    OctreeNode& node = nodes_[index];
    for (int a = 0; a < 3; ++a) {
      node.lo[a] = std::numeric_limits<float>::infinity();
      node.hi[a] = -std::numeric_limits<float>::infinity();
    }
    node.minFace = UINT32_MAX;
    for (uint32_t c = first; c < child; ++c) {
      node.minFace = std::min(node.minFace, nodes_[c].minFace);
      for (int a = 0; a < 3; ++a) {
        node.lo[a] = std::min(node.lo[a], nodes_[c].lo[a]);
        node.hi[a] = std::max(node.hi[a], nodes_[c].hi[a]);
      }
    }
  }

  void leafBounds(uint32_t index) {
    OctreeNode& node = nodes_[index];
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    node.minFace = UINT32_MAX;
    for (uint32_t i = node.faceBegin; i < node.faceEnd; ++i) {
      const uint32_t id = faces_[i];
      node.minFace = std::min(node.minFace, id);
      const FaceRef face = scene_.locate(id);
      const uint32_t n = mesh_.cornerCount(face.meshFace);
      const Corner* c = mesh_.faceCorners(face.meshFace);
      for (uint32_t j = 0; j < n; ++j) {
        const Vec3 w = world(face.instance, uint32_t(c[j].position));
        for (int a = 0; a < 3; ++a) {
          lo[a] = std::min(lo[a], w[a]);
          hi[a] = std::max(hi[a], w[a]);
        }
      }
    }
    for (int a = 0; a < 3; ++a) {
      // Round outward so the float box contains the double one.
      float l = float(lo[a]), h = float(hi[a]);
      if (double(l) > lo[a]) l = std::nextafter(l, -std::numeric_limits<float>::infinity());
      if (double(h) < hi[a]) h = std::nextafter(h, std::numeric_limits<float>::infinity());
      node.lo[a] = l;
      node.hi[a] = h;
    }
  }

  // Position p of instance k in world space.
  Vec3 world(uint32_t k, uint32_t p) const {
    if (!shared_) return transformPoint(scene_.modelMatrix(k), mesh_.positions[p]);
    const Vec3& r = rotated_[p];
    const Vec3& offset = offsets_[k];
    return Vec3(r[0] + offset[0], r[1] + offset[1], r[2] + offset[2]);
  }

  const Scene& scene_;
  const Mesh& mesh_;
  uint32_t leafFaces_;  // a node with at most this many faces is a leaf
  std::vector<OctreeNode>& nodes_;
  std::vector<uint32_t>& faces_;
  bool shared_ = false;        // every instance: the whole mesh, the same rotation
  std::vector<Vec3> rotated_;  // with shared_: mesh positions after the model rotation
  std::vector<Vec3> offsets_;  // per instance: its matrix's translation
  std::vector<uint32_t> codes_;
  Vec3 origin_;
  double cellScale_ = 1.0, side_ = 1.0;
  float margin_ = 0.0f;
};

}  // namespace

void Octree::build(const Scene& scene, uint32_t leafFaces) {
  nodes_.clear();
  faces_.clear();
  Builder(scene, leafFaces, nodes_, faces_).build();
  nodes_.shrink_to_fit();
}

}  // namespace zrender
