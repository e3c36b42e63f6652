#include "zrender/raster/DepthPyramid.hpp"

#include <immintrin.h>

#include <algorithm>
#include <climits>

#include "zrender/base/CpuFeatures.hpp"
#include "zrender/raster/KeyFill.hpp"

namespace zrender {

TileMax tileMax(const DepthKey* first, size_t stride, int rows, int columns) {
  // The maximum of each row (branch-free), the last row holding the overall maximum, then the
  // last sample of that row holding it.
  TileMax m;
  for (int y = 0; y < rows; ++y) {
    const DepthKey* row = first + size_t(y) * stride;
    DepthKey rowMax = row[0];
    for (int i = 1; i < columns; ++i) rowMax = std::max(rowMax, row[i]);
    m.row = rowMax >= m.key ? y : m.row;
    m.key = std::max(m.key, rowMax);
  }
  const DepthKey* row = first + size_t(m.row) * stride;
  m.column = columns - 1;
  while (m.column > 0 && row[m.column] != m.key) --m.column;
  return m;
}

namespace {

// Keys with the top bit flipped: unsigned 64-bit order becomes the signed order AVX2 compares.
ZRENDER_AVX2 inline __m256i loadFlipped(const DepthKey* p) {
  return _mm256_xor_si256(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(p)),
                          _mm256_set1_epi64x(INT64_MIN));
}
ZRENDER_AVX2 inline __m256i maxFlipped(__m256i a, __m256i b) {
  return _mm256_blendv_epi8(a, b, _mm256_cmpgt_epi64(b, a));
}
// Bit i set when key i of the four equals the flipped `wanted`.
ZRENDER_AVX2 inline unsigned equalMask(const DepthKey* p, __m256i wanted) {
  return unsigned(
      _mm256_movemask_pd(_mm256_castsi256_pd(_mm256_cmpeq_epi64(loadFlipped(p), wanted))));
}

}  // namespace

ZRENDER_AVX2 TileMax tileMaxAvx2(const DepthKey* first, size_t stride, int rows) {
  static_assert(DepthPyramid::kTileSize == 16, "four vectors of four keys per row");
  // The maximum over the tile, four independent column vectors at a time.
  __m256i m0 = loadFlipped(first), m1 = loadFlipped(first + 4), m2 = loadFlipped(first + 8),
          m3 = loadFlipped(first + 12);
  for (int y = 1; y < rows; ++y) {
    const DepthKey* row = first + size_t(y) * stride;
    m0 = maxFlipped(m0, loadFlipped(row));
    m1 = maxFlipped(m1, loadFlipped(row + 4));
    m2 = maxFlipped(m2, loadFlipped(row + 8));
    m3 = maxFlipped(m3, loadFlipped(row + 12));
  }
  const __m256i m = maxFlipped(maxFlipped(m0, m1), maxFlipped(m2, m3));
  alignas(32) int64_t lanes[4];
  _mm256_store_si256(reinterpret_cast<__m256i*>(lanes), m);
  const int64_t best = std::max(std::max(lanes[0], lanes[1]), std::max(lanes[2], lanes[3]));
  // The last row holding it, from the bottom, and its last sample holding it.
  const __m256i wanted = _mm256_set1_epi64x(best);
  TileMax out;
  out.key = DepthKey(best) ^ DepthKey(INT64_MIN);
  for (int y = rows - 1; y >= 0; --y) {
    const DepthKey* row = first + size_t(y) * stride;
    const unsigned mask = equalMask(row, wanted) | equalMask(row + 4, wanted) << 4 |
                          equalMask(row + 8, wanted) << 8 | equalMask(row + 12, wanted) << 12;
    if (mask) {
      out.row = y;
      out.column = 31 - __builtin_clz(mask);
      return out;
    }
  }
  return out;  // not reached: the maximum is in some row
}

void DepthPyramid::begin(FrameBuffer& fb, int rowBegin, int rowEnd) {
  keys_ = fb.row(rowBegin);
  rowOffset_ = rowBegin;
  avx2_ = cpuHasAvx2();
  if (fb.width() != width_ || rowEnd - rowBegin != height_ || levels_.empty()) {
    width_ = fb.width();
    height_ = rowEnd - rowBegin;
    tilesX_ = (width_ + kTileSize - 1) >> kTileShift;
    tilesY_ = (height_ + kTileSize - 1) >> kTileShift;
    levels_.clear();
    levelWidth_.clear();
    levelHeight_.clear();
    int w = std::max(tilesX_, 1), h = std::max(tilesY_, 1);
    for (;;) {
      levels_.emplace_back(size_t(w) * size_t(h));
      levelWidth_.push_back(w);
      levelHeight_.push_back(h);
      if (w == 1 && h == 1) break;
      w = (w + 1) / 2;
      h = (h + 1) / 2;
    }
    const size_t tiles = size_t(tilesX_) * size_t(tilesY_);
    tileArgMax_.resize(tiles);
    rowCleared_.resize(size_t(tilesY_));
  }
  for (auto& level : levels_) std::fill(level.begin(), level.end(), kClearKey);
  std::fill(rowCleared_.begin(), rowCleared_.end(), uint8_t(0));
}

void DepthPyramid::clearTileRow(int ty) {
  const int y0 = ty << kTileShift, y1 = std::min(y0 + kTileSize, height_);
  fillKeys(rowPointer(y0), size_t(y1 - y0) * size_t(width_), kClearKey);
  // Any sample holds the maximum of a clear tile; the last one is reached last by triangles
  // drawn top to bottom, which postpones the first rescan.
  uint32_t* argMax = tileArgMax_.data() + size_t(ty) * tilesX_;
  for (int tx = 0; tx < tilesX_; ++tx) {
    const int lastX = std::min((tx + 1) << kTileShift, width_) - 1;
    argMax[tx] = uint32_t(size_t(y1 - 1) * size_t(width_) + size_t(lastX));
  }
  rowCleared_[size_t(ty)] = 1;
}

void DepthPyramid::rescanTile(int tx, int ty) {
  const int x0 = tx << kTileShift, y0 = ty << kTileShift;
  const int x1 = std::min(x0 + kTileSize, width_), y1 = std::min(y0 + kTileSize, height_);
  const size_t t = size_t(ty) * tilesX_ + tx;
  if (levels_[0][t] == kClearKey) {
    // A tile with clear samples keeps kClearKey as its maximum while any remains: if one of a
    // sparse grid of its samples is still clear (bottom rows first: triangles come top to
    // bottom), it holds the maximum, and the tile need not be scanned.
    for (int y = y1 - 1; y >= y0; y -= 5) {
      const DepthKey* row = rowPointer(y);
      for (int x = x1 - 1; x >= x0; x -= 5) {
        if (row[x] == kClearKey) {
          tileArgMax_[t] = uint32_t(size_t(y) * size_t(width_) + size_t(x));
          return;
        }
      }
    }
  }
  const TileMax m = avx2_ && x1 - x0 == kTileSize
                        ? tileMaxAvx2(rowPointer(y0) + x0, size_t(width_), y1 - y0)
                        : tileMax(rowPointer(y0) + x0, size_t(width_), y1 - y0, x1 - x0);
  const DepthKey best = m.key;
  tileArgMax_[t] = uint32_t(size_t(y0 + m.row) * size_t(width_) + size_t(x0 + m.column));
  if (best == levels_[0][t]) return;
  levels_[0][t] = best;
  propagate(tx, ty);
}

void DepthPyramid::propagate(int tx, int ty) {
  // Recompute parents from their (up to four) children while the maximum keeps changing.
  int x = tx, y = ty;
  for (size_t level = 1; level < levels_.size(); ++level) {
    x >>= 1;
    y >>= 1;
    const std::vector<DepthKey>& child = levels_[level - 1];
    const int cw = levelWidth_[level - 1], ch = levelHeight_[level - 1];
    const int cx0 = 2 * x, cy0 = 2 * y;
    const int cx1 = std::min(cx0 + 1, cw - 1), cy1 = std::min(cy0 + 1, ch - 1);
    DepthKey m = child[size_t(cy0) * cw + cx0];
    m = std::max(m, child[size_t(cy0) * cw + cx1]);
    m = std::max(m, child[size_t(cy1) * cw + cx0]);
    m = std::max(m, child[size_t(cy1) * cw + cx1]);
    DepthKey& node = levels_[level][size_t(y) * levelWidth_[level] + x];
    if (node == m) return;
    node = m;
  }
}

bool DepthPyramid::occludesSlow(int x0, int y0, int x1, int y1, DepthKey key, int maxNodes) const {
  // Coarsest useful level: the tile rectangle meets at most 2 x 2 of its nodes.
  const int top = int(levels_.size()) - 1;
  int level = std::min(1, top);
  while (level < top && ((x1 >> level) - (x0 >> level) > 1 || (y1 >> level) - (y0 >> level) > 1))
    ++level;
  // Then finer levels, whose nodes hug the rectangle better, while they stay cheap.
  for (;;) {
    if (key > maxOver(level, x0 >> level, y0 >> level, x1 >> level, y1 >> level)) return true;
    if (level == 0) return false;
    --level;
    const int nx = (x1 >> level) - (x0 >> level) + 1, ny = (y1 >> level) - (y0 >> level) + 1;
    if (nx * ny > maxNodes) return false;
  }
}

void DepthPyramid::finish() {
  for (int ty = 0; ty < tilesY_; ++ty)
    if (!rowCleared_[size_t(ty)]) clearTileRow(ty);
}

}  // namespace zrender
