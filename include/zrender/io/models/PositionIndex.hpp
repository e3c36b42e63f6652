#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

#include "zrender/scene/Transforms.hpp"

namespace zrender {

// Positions equal to the last bit made one vertex, as an OBJ `v` shared by its faces: STL gives
// every triangle its own three corners, and smooth normals need the faces around a vertex to
// share it (docs/design.md, Model formats). An open-addressing table of indices into the
// positions: a node-based map's allocations cost more than the rest of the read.
class PositionIndex {
 public:
  explicit PositionIndex(std::vector<Vec3>& positions) : positions_(positions) {}

  // The index of `p` in the positions, appended when it is new.
  int32_t find(const Vec3& p) {
    if ((positions_.size() + 1) * 2 > slots_.size()) grow();
    const size_t mask = slots_.size() - 1;
    for (size_t i = hash(p) & mask;; i = (i + 1) & mask) {
      const int32_t index = slots_[i];
      if (index < 0) {
        slots_[i] = int32_t(positions_.size());
        positions_.push_back(p);
        return slots_[i];
      }
      if (std::memcmp(positions_[size_t(index)].val, p.val, sizeof p.val) == 0) return index;
    }
  }

 private:
  static size_t hash(const Vec3& p) {
    uint64_t b[3];
    std::memcpy(b, p.val, sizeof b);
    uint64_t h = b[0] * 0x9E3779B97F4A7C15ull;
    h = (h ^ (h >> 31) ^ b[1]) * 0xBF58476D1CE4E5B9ull;
    h = (h ^ (h >> 29) ^ b[2]) * 0x94D049BB133111EBull;
    return size_t(h ^ (h >> 32));
  }

  void grow() {
    slots_.assign(std::max<size_t>(1024, slots_.size() * 2), -1);
    const size_t mask = slots_.size() - 1;
    for (size_t k = 0; k < positions_.size(); ++k) {
      size_t i = hash(positions_[k]) & mask;
      while (slots_[i] >= 0) i = (i + 1) & mask;
      slots_[i] = int32_t(k);
    }
  }

  std::vector<Vec3>& positions_;
  std::vector<int32_t> slots_;
};

}  // namespace zrender
