#include "zrender/cli/bench/MachineProbe.hpp"

#include <algorithm>

#include "zrender/base/Clock.hpp"

namespace zrender {

MachineProbe::MachineProbe() : depths_(size_t(1) << 20, 1e30f) {}

double MachineProbe::runMs() {
  const double start = nowMs();
  float sum = 0;
  // A depth test against a plane over 4 MiB, the inner loop of a z-buffer through the caches,
  // as a frame of a model of some megabytes goes.
  for (size_t i = 0; i < depths_.size(); ++i) {
    depths_[i] = std::min(depths_[i], 0.5f * float(i));
    sum += depths_[i];
  }
  sink_ = sink_ + sum;
  return nowMs() - start;
}

}  // namespace zrender
