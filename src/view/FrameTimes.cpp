#include "zrender/view/FrameTimes.hpp"

#include <vector>

#include "zrender/base/Median.hpp"

namespace zrender {

void FrameTimes::add(double frameMs, double shownAtMs) {
  frameMs_.push_back(frameMs);
  shownAtMs_.push_back(shownAtMs);
  if (frameMs_.size() > kFrames) {
    frameMs_.pop_front();
    shownAtMs_.pop_front();
  }
}

double FrameTimes::medianFrameMs() const {
  return median(std::vector<double>(frameMs_.begin(), frameMs_.end()));
}

double FrameTimes::framesPerSecond() const {
  if (shownAtMs_.size() < 2) return 0.0;
  const double span = shownAtMs_.back() - shownAtMs_.front();
  return span > 0.0 ? 1000.0 * double(shownAtMs_.size() - 1) / span : 0.0;
}

}  // namespace zrender
