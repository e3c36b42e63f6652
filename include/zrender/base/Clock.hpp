#pragma once

#include <chrono>

namespace zrender {

// Milliseconds since an arbitrary start (the steady clock).
inline double nowMs() {
  using namespace std::chrono;
  return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}

// Adds the milliseconds between its construction and its destruction to `total`: the one way
// the pipeline times a stage.
class ScopedTimer {
 public:
  explicit ScopedTimer(double& total) : total_(total), start_(nowMs()) {}
  ~ScopedTimer() { total_ += nowMs() - start_; }
  ScopedTimer(const ScopedTimer&) = delete;
  ScopedTimer& operator=(const ScopedTimer&) = delete;

 private:
  double& total_;
  double start_;
};

}  // namespace zrender
