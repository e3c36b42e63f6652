#pragma once

#include <vector>

namespace zrender {

// A fixed piece of work timed before every bench frame: how fast the machine is at that moment.
// On a shared virtual machine the speed of one core changes by up to 1.7 times within a
// second (docs/bench.md, The machine-speed probe). A comparison with a baseline also divides
// each frame by the probes beside it, where such a change cancels and a change of zrender's
// code does not; a slowdown counts only when it shows both ways. The work must stay the same
// from version to version: baselines are compared through it.
class MachineProbe {
 public:
  MachineProbe();
  // Runs the work once (about 1.7 ms on an AMD EPYC core) and returns its wall time, ms.
  double runMs();

 private:
  std::vector<float> depths_;  // 4 MiB: a probe within L2 tracked frames less well (docs/bench.md)
  volatile float sink_ = 0;    // what the work computes, so that it cannot be left out
};

}  // namespace zrender
