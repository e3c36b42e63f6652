#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "zrender/base/Threads.hpp"

namespace zrender {

// Bands per thread for the algorithms that draw bands of rows from tables of their own (the
// scan-line ones): enough for the threads to balance uneven bands, few enough that the faces
// crossing band edges, classified in each band they reach, stay a small share.
constexpr int kBandsPerThread = 8;

// An image's sample rows cut into bands of about equal height, for algorithms that draw the
// bands apart (one thread each) and need every item that reaches a band in that band's list.
class RowBands {
 public:
  // `height` rows in about `count` bands (at least one) of equal height, a multiple of `align`
  // rows, over the rows [busyBegin, busyEnd) where the work is (default: all): the rows
  // before and after them go to the first and the last band.
  RowBands(int height, int count, int align = 1, int busyBegin = 0, int busyEnd = -1)
      : height_(std::max(height, 0)) {
    count = std::max(count, 1);
    busyEnd = busyEnd < 0 ? height_ : std::min(busyEnd, height_);
    busyBegin = std::clamp(busyBegin, 0, busyEnd);
    rowsPerBand_ = std::max(align, (busyEnd - busyBegin + count - 1) / count);
    rowsPerBand_ = (rowsPerBand_ + align - 1) / align * align;
    // The first band's end: the first multiple of the band height past busyBegin, from 0
    // (so that band edges stay aligned).
    first_ = std::min(height_, (busyBegin / rowsPerBand_ + 1) * rowsPerBand_);
    count_ = 1 + std::max(0, (height_ - first_ + rowsPerBand_ - 1) / rowsPerBand_);
    count_ =
        std::min(count_, 1 + std::max(0, (busyEnd - first_ + rowsPerBand_ - 1) / rowsPerBand_));
  }
  int count() const { return count_; }
  int rowBegin(int band) const { return band == 0 ? 0 : first_ + (band - 1) * rowsPerBand_; }
  int rowEnd(int band) const {
    return band + 1 == count_ ? height_ : std::min(height_, first_ + band * rowsPerBand_);
  }
  int bandOf(int row) const {
    return row < first_ ? 0 : std::min(count_ - 1, 1 + (row - first_) / rowsPerBand_);
  }

 private:
  int height_, rowsPerBand_, first_, count_;
};

// Items 0..n-1 (triangles, faces) placed in every band of rows they reach, in increasing order
// within a band: a counting sort over chunks of items, counted and placed by several threads.
class BandPlacer {
 public:
  // rowsOf(i, first, last) gives item i's rows [first, last] inside the image, or false when
  // it reaches none; size(total) is told how many places there are, then place(i, k) puts
  // item i at position k, band b's items being at positions [start(b), start(b + 1)).
  template <typename RowsOf, typename Size, typename Place>
  void place(size_t n, const RowBands& bands, const Threads& threads, const RowsOf& rowsOf,
             const Size& size, const Place& place) {
    placeSegments(
        std::vector<size_t>{n}, bands, threads,
        [&](size_t, size_t i, int& first, int& last) { return rowsOf(i, first, last); }, size,
        [&](size_t, size_t i, uint32_t k) { place(i, k); });
  }

  // The same for items in segments (the parts of a frame's geometry), segment after segment:
  // rowsOf(segment, i, first, last) and place(segment, i, k) for item i of a segment.
  template <typename RowsOf, typename Size, typename Place>
  void placeSegments(const std::vector<size_t>& segments, const RowBands& bands,
                     const Threads& threads, const RowsOf& rowsOf, const Size& size,
                     const Place& place) {
    constexpr size_t kChunk = 4096;
    constexpr uint32_t kNone = ~uint32_t(0);
    using Chunk = ChunkRange;
    chunks_.clear();
    size_t n = 0;
    for (size_t s = 0; s < segments.size(); ++s) {
      for (size_t b = 0; b < segments[s]; b += kChunk)
        chunks_.push_back(Chunk{s, b, std::min(segments[s], b + kChunk), n + b});
      n += segments[s];
    }
    const size_t count = size_t(bands.count()), chunks = chunks_.size();
    cursor_.assign(chunks * count, 0);
    range_.resize(n);  // each item's first and last band, from the counting pass
    // Each row's band: a look-up, not bandOf()'s division, for every item.
    bandOfRow_.resize(size_t(bands.rowEnd(bands.count() - 1)));
    for (int b = 0; b < bands.count(); ++b)
      std::fill(bandOfRow_.begin() + bands.rowBegin(b), bandOfRow_.begin() + bands.rowEnd(b),
                uint16_t(b));
    threads.forEach(chunks, [&](size_t c) {
      const Chunk& k = chunks_[c];
      uint32_t* counts = cursor_.data() + c * count;
      for (size_t i = k.begin; i < k.end; ++i) {
        uint32_t& range = range_[k.first + i - k.begin];
        int first = 0, last = 0;
        if (!rowsOf(k.segment, i, first, last)) {
          range = kNone;
          continue;
        }
        const uint32_t b0 = bandOfRow_[size_t(first)], b1 = bandOfRow_[size_t(last)];
        range = b0 << 16 | b1;
        for (uint32_t b = b0; b <= b1; ++b) ++counts[b];
      }
    });
    // The counts become each (chunk, band)'s first position.
    start_.assign(count + 1, 0);
    uint32_t total = 0;
    for (size_t b = 0; b < count; ++b) {
      start_[b] = total;
      for (size_t c = 0; c < chunks; ++c) {
        const uint32_t k = cursor_[c * count + b];
        cursor_[c * count + b] = total;
        total += k;
      }
    }
    start_[count] = total;
    size(total);
    threads.forEach(chunks, [&](size_t c) {
      const Chunk& k = chunks_[c];
      uint32_t* at = cursor_.data() + c * count;
      for (size_t i = k.begin; i < k.end; ++i) {
        const uint32_t range = range_[k.first + i - k.begin];
        if (range == kNone) continue;
        for (uint32_t b = range >> 16; b <= (range & 0xFFFF); ++b) place(k.segment, i, at[b]++);
      }
    });
  }

  uint32_t start(int band) const { return start_[size_t(band)]; }
  const std::vector<uint32_t>& starts() const { return start_; }

 private:
  struct ChunkRange {
    size_t segment, begin, end, first;  // items [begin, end) of a segment; first: overall
  };
  std::vector<uint32_t> start_, cursor_;
  // Band numbers fit 16 bits: a band has a row at least, and an image at most 32768 rows.
  std::vector<uint32_t> range_;  // first band << 16 | last band
  std::vector<uint16_t> bandOfRow_;
  std::vector<ChunkRange> chunks_;
};

// The items of each band, as BandPlacer places them: itemOf(segment, i) for item i of a
// segment (an index, a pointer).
template <class Item>
class BandLists {
 public:
  template <typename RowsOf, typename ItemOf>
  void build(const std::vector<size_t>& segments, const RowBands& bands, const Threads& threads,
             const RowsOf& rowsOf, const ItemOf& itemOf) {
    placer_.placeSegments(
        segments, bands, threads, rowsOf, [&](uint32_t total) { items_.resize(total); },
        [&](size_t segment, size_t i, uint32_t k) { items_[k] = itemOf(segment, i); });
  }

  const Item* items(int band) const { return items_.data() + placer_.start(band); }
  size_t size(int band) const { return placer_.start(band + 1) - placer_.start(band); }

 private:
  BandPlacer placer_;
  std::vector<Item> items_;
};

}  // namespace zrender
