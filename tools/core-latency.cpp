// zrender-core-latency [ROUNDS]: how long a cache line takes to go from one processor to
// another, for each pair of the machine's first processors (up to 4), in nanoseconds one way:
// two threads pinned to the pair hand a counter back and forth. On a virtual machine the host
// decides where the virtual processors run, and this moves from hour to hour (27 to 235 ns on
// one day here); every phase of a frame that one thread writes and another reads pays it, so
// the speed-ups over one thread are worth reading only beside it (docs/performance.md,
// Threads). A developer's measurement, run by hand; not part of `zrender` or of CI.
#include <pthread.h>
#include <sched.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>

namespace {

bool pinTo(int cpu) {
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(cpu, &set);
  return pthread_setaffinity_np(pthread_self(), sizeof set, &set) == 0;
}

// Nanoseconds one way, median of 5 runs of `rounds` round trips; negative when a thread
// cannot be pinned.
double oneWay(int a, int b, int rounds) {
  double runs[5];
  for (double& ns : runs) {
    alignas(64) std::atomic<int> turn{0};
    std::atomic<bool> pinned{true};
    std::thread other([&] {
      if (!pinTo(b)) pinned = false;
      for (int i = 0; i < rounds; ++i) {
        while (turn.load(std::memory_order_acquire) != 2 * i + 1) {
        }
        turn.store(2 * i + 2, std::memory_order_release);
      }
    });
    if (!pinTo(a)) pinned = false;
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < rounds; ++i) {
      turn.store(2 * i + 1, std::memory_order_release);
      while (turn.load(std::memory_order_acquire) != 2 * i + 2) {
      }
    }
    const auto end = std::chrono::steady_clock::now();
    other.join();
    if (!pinned) return -1.0;
    ns = std::chrono::duration<double, std::nano>(end - start).count() / rounds / 2;
  }
  std::sort(runs, runs + 5);
  return runs[2];
}

}  // namespace

int main(int argc, char** argv) {
  const int rounds = argc > 1 ? std::atoi(argv[1]) : 100000;
  const int cpus = std::min(4, int(std::thread::hardware_concurrency()));
  if (rounds < 1 || cpus < 2) {
    std::fprintf(stderr, "usage: zrender-core-latency [ROUNDS > 0], on 2 or more processors\n");
    return 2;
  }
  for (int a = 0; a < cpus; ++a)
    for (int b = a + 1; b < cpus; ++b) {
      const double ns = oneWay(a, b, rounds);
      if (ns < 0) {
        std::fprintf(stderr, "zrender-core-latency: cannot pin threads to processors %d, %d\n", a,
                     b);
        return 1;
      }
      std::printf("processors %d and %d: %.0f ns one way\n", a, b, ns);
    }
  return 0;
}
