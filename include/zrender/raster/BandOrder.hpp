#pragma once

#include <cstdint>
#include <vector>

#include "zrender/base/Clock.hpp"
#include "zrender/base/Threads.hpp"
#include "zrender/raster/RowBands.hpp"

namespace zrender {

// Starts an image's bands on several threads longest first, by the time the last frame took
// over their rows: a long band started last ends last while the other threads wait, so the
// threads end together as nearly as the bands allow. The order changes when each band starts,
// never what it draws. One per algorithm instance: it keeps the last frame's times.
class BandOrder {
 public:
  // drawBand(b) for every band of `rows`, on `threads`, the longest first (in row order for a
  // first frame or an image of another height); each band's time is kept for the next frame.
  template <typename DrawBand>
  void forEachBand(const Threads& threads, const RowBands& rows, const DrawBand& drawBand) {
    const std::vector<uint32_t> order = longestFirst(rows);
    bandMs_.assign(size_t(rows.count()), 0.0);
    threads.forEachInOrder(order, [&](size_t b) {
      ScopedTimer timer(bandMs_[b]);
      drawBand(b);
    });
    keep(rows, bandMs_);
  }

  // The bands of `rows` by the time kept over their rows, longest first (equal times in row
  // order).
  std::vector<uint32_t> longestFirst(const RowBands& rows) const;
  // Keeps the times `bandMs` (ms) of the bands of `rows`, each spread evenly over its rows, so
  // that the next order can be found for bands cut elsewhere.
  void keep(const RowBands& rows, const std::vector<double>& bandMs);

 private:
  std::vector<double> bandMs_;  // this frame's, per band
  std::vector<double> rowMs_;   // kept, per sample row
};

}  // namespace zrender
