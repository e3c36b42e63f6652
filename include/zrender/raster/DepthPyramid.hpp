#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "zrender/raster/FrameBuffer.hpp"
#include "zrender/raster/RasterRules.hpp"

namespace zrender {

// Where the largest key of a tile lies.
struct TileMax {
  DepthKey key = 0;
  int row = 0, column = 0;  // within the tile
};

// The largest key of the `rows` x `columns` samples from `first` (rows `stride` keys apart),
// in the last row holding it, at the last sample of that row holding it (for a tile with
// samples still clear: the bottom-right-most, which triangles drawn top to bottom reach last).
TileMax tileMax(const DepthKey* first, size_t stride, int rows, int columns);
// The same for a whole tile (16 columns) with AVX2: same result, for CPUs that have it.
TileMax tileMaxAvx2(const DepthKey* first, size_t stride, int rows);

// The z-pyramid of Greene, Kass and Miller (1993) over a FrameBuffer: a max-quadtree of depth
// keys. Level 0 holds one node per tile of kTileSize x kTileSize samples; each coarser level
// halves both dimensions, up to one node. A node's value is never smaller than the largest key
// of the samples below it, so "key > node" proves that a key loses the depth test (tie-break
// included) at every one of those samples.
//
// Tiles of 16 x 16 samples measured best against 4, 8 and 32 (docs/performance.md): a small
// triangle touches few of them, so there are few tiles to check and to rescan after it, and
// coarser tiles cull less.
//
// Keeping it up to date without rescanning tiles after every triangle: each tile remembers
// which sample holds its maximum (for a clear tile, its last sample). Keys only decrease, so
// the maximum is unchanged until that sample is written; update() checks that one sample per
// tile a triangle touched, rescans only then, and propagates a change upward only while it
// changes the parent. A tile that still has clear samples first looks for one on a sparse grid
// of 16 samples, which then holds the maximum, unchanged: most rescans end there. A full rescan
// takes four keys at a time with AVX2 (tileMaxAvx2). A stale node (too large) would still be a
// valid bound.
//
// The pyramid also clears the buffer lazily, a row of tiles at a time just before triangles
// first reach it (prepareRows); finish() clears what no triangle reached. Logically every
// sample is kClearKey from begin() on.
class DepthPyramid {
 public:
  static constexpr int kTileShift = 4;               // 16 x 16 samples
  static constexpr int kTileSize = 1 << kTileShift;  // samples per tile side

  // Starts a frame on `fb` (already sized): every sample is logically kClearKey.
  void begin(FrameBuffer& fb) { begin(fb, 0, fb.height()); }
  // The same over sample rows [rowBegin, rowEnd) of `fb` alone (rowBegin a multiple of
  // kTileSize): the pyramid of a band of the image, which one thread draws. Rows below are in
  // image coordinates all the same.
  void begin(FrameBuffer& fb, int rowBegin, int rowEnd);

  // Clears the sample rows [minY, maxY] (inside the image) before a triangle writes there, if
  // not done yet this frame: whole rows of tiles at a time, so that the stores stream through
  // memory and the rows are in cache for the triangles that follow.
  void prepareRows(int minY, int maxY) {
    minY -= rowOffset_;
    maxY -= rowOffset_;
    for (int ty = minY >> kTileShift; ty <= maxY >> kTileShift; ++ty)
      if (!rowCleared_[size_t(ty)]) clearTileRow(ty);
  }

  // Brings the pyramid up to date after a triangle wrote into the sample rectangle.
  void update(int minX, int minY, int maxX, int maxY) {
    const int tx0 = minX >> kTileShift, tx1 = maxX >> kTileShift;
    const int ty0 = (minY - rowOffset_) >> kTileShift, ty1 = (maxY - rowOffset_) >> kTileShift;
    const DepthKey* keys = keys_;
    for (int ty = ty0; ty <= ty1; ++ty) {
      const size_t rowTile = size_t(ty) * tilesX_;
      for (int tx = tx0; tx <= tx1; ++tx) {
        const size_t t = rowTile + tx;
        // Unchanged while the sample that held the maximum still holds it.
        if (keys[tileArgMax_[t]] != levels_[0][t]) rescanTile(tx, ty);
      }
    }
  }

  // True when `key` is greater than every key in the sample rectangle (inclusive, inside the
  // image): a primitive whose keys are all >= `key` there cannot change the buffer. Looks at
  // the 2 x 2 nodes of the coarsest level that covers the rectangle, then at finer levels
  // while they have at most `maxNodes` nodes over it.
  bool occludes(int minX, int minY, int maxX, int maxY, DepthKey key, int maxNodes = 16) const {
    const int x0 = minX >> kTileShift, x1 = maxX >> kTileShift;
    const int y0 = (minY - rowOffset_) >> kTileShift, y1 = (maxY - rowOffset_) >> kTileShift;
    if (x1 - x0 <= 1 && y1 - y0 <= 1) {
      // Small rectangles (most triangles): the at most 2 x 2 tiles themselves.
      const DepthKey* tiles = levels_[0].data();
      const DepthKey* r0 = tiles + size_t(y0) * tilesX_;
      const DepthKey* r1 = tiles + size_t(y1) * tilesX_;
      return key > std::max(std::max(r0[x0], r0[x1]), std::max(r1[x0], r1[x1]));
    }
    return occludesSlow(x0, y0, x1, y1, key, maxNodes);
  }

  // For the tiles of the sample rectangle [minX, maxX] x [minY, maxY] (inside the pyramid's
  // rows): sets hidden[t] (one byte per tile of the image, row by row; grown to this
  // pyramid's last tile if smaller) to whether `key` is greater than every key of tile t,
  // valid until the pyramid changes; or, with key 0, to 0.
  void tilesBehind(DepthKey key, int minX, int minY, int maxX, int maxY,
                   std::vector<uint8_t>& hidden) const {
    const std::vector<DepthKey>& tiles = levels_[0];
    const size_t firstTile = size_t(rowOffset_ >> kTileShift) * size_t(tilesX_);
    if (hidden.size() < firstTile + tiles.size()) hidden.resize(firstTile + tiles.size());
    uint8_t* out = hidden.data() + firstTile;
    for (int ty = (minY - rowOffset_) >> kTileShift; ty <= (maxY - rowOffset_) >> kTileShift;
         ++ty) {
      const size_t row = size_t(ty) * size_t(tilesX_);
      for (int tx = minX >> kTileShift; tx <= maxX >> kTileShift; ++tx)
        out[row + size_t(tx)] = key > tiles[row + size_t(tx)];
    }
  }
  int tilesX() const { return tilesX_; }

  // Clears the tiles that no triangle reached; the buffer is then final.
  void finish();

  int levelCount() const { return int(levels_.size()); }

 private:
  bool occludesSlow(int x0, int y0, int x1, int y1, DepthKey key, int maxNodes) const;
  void clearTileRow(int ty);
  void rescanTile(int tx, int ty);
  void propagate(int tx, int ty);
  // Largest node value over nodes [x0, x1] x [y0, y1] of `level`.
  DepthKey maxOver(int level, int x0, int y0, int x1, int y1) const {
    const DepthKey* nodes = levels_[size_t(level)].data();
    const int w = levelWidth_[size_t(level)];
    DepthKey m = 0;
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) m = std::max(m, nodes[size_t(y) * w + x]);
    return m;
  }

  DepthKey* rowPointer(int y) const { return keys_ + size_t(y) * size_t(width_); }

  DepthKey* keys_ = nullptr;    // the first sample of the pyramid's first row
  int rowOffset_ = 0;           // that row in the image
  int width_ = 0, height_ = 0;  // samples
  int tilesX_ = 0, tilesY_ = 0;
  std::vector<std::vector<DepthKey>> levels_;  // levels_[0]: tiles; last: the root
  std::vector<int> levelWidth_, levelHeight_;
  std::vector<uint32_t> tileArgMax_;  // cleared tiles: sample index (from keys_) of the maximum
  std::vector<uint8_t> rowCleared_;   // per row of tiles: cleared this frame
  bool avx2_ = false;                 // tileMaxAvx2 for whole tiles
};

}  // namespace zrender
