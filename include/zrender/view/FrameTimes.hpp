#pragma once

#include <cstddef>
#include <deque>

namespace zrender {

// The viewer's timing figures over its last kFrames frames (since the algorithm, shading, MSAA
// or culling last changed): the median frame time (transform + raster, FrameTimings::frameMs)
// and the frames shown per second.
class FrameTimes {
 public:
  static constexpr size_t kFrames = 30;

  // A frame that took `frameMs` to render and was shown at `shownAtMs` (nowMs()).
  void add(double frameMs, double shownAtMs);

  size_t count() const { return frameMs_.size(); }
  double medianFrameMs() const;  // 0 before the first frame
  // Frames per second between the first and the last of the kept frames; 0 before two frames.
  double framesPerSecond() const;

 private:
  std::deque<double> frameMs_, shownAtMs_;
};

}  // namespace zrender
