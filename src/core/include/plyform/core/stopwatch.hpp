#pragma once
// Wall seconds of the passes of a cycle, for the per-pass timing every run reports
// (engine/pass_timing.hpp): one steady-clock read per lap (some 20 ns through the vDSO), cheap
// enough to stay on.

#include <chrono>

namespace plyform::core {

class Stopwatch {
 public:
  Stopwatch() : last_(Clock::now()) {}
  /// Seconds since the construction or the last lap; the next lap starts now.
  double lap() {
    const Clock::time_point now = Clock::now();
    const double s = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return s;
  }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point last_;
};

}  // namespace plyform::core
