#include "plyform/engine/thread_governor.hpp"

#include <algorithm>
#include <ctime>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace plyform::engine {
namespace {

// A window long enough to hold many cycles and to outlast a scheduler's time slices, short
// enough to react within a second.
constexpr double kWindow = 0.25;  // [s]

double process_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

double seconds(std::chrono::steady_clock::duration d) {
  return std::chrono::duration<double>(d).count();
}

}  // namespace

ThreadPolicy::ThreadPolicy(int requested)
    : requested_(std::max(1, requested)), current_(requested_) {}

int ThreadPolicy::on_window(double cpu_per_thread, double now) {
  if (requested_ == 1)
    return current_;
  if (current_ == requested_) {
    // Two windows in a row, so that one slow output write does not count.
    low_windows_ = cpu_per_thread < kShared ? low_windows_ + 1 : 0;
    if (low_windows_ >= 2) {
      low_windows_ = 0;
      ++reductions_;
      current_ = 1;
      probe_at_ = now + backoff_;
      backoff_ = std::min(2.0 * backoff_, kMaxBackoff);
    } else if (low_windows_ == 0) {
      backoff_ = std::max(kFirstBackoff, 0.5 * backoff_);  // the cores are the run's again
    }
  } else if (now >= probe_at_) {
    current_ = requested_;  // probe: the next windows judge it
  }
  return current_;
}

ThreadGovernor::ThreadGovernor(int threads) : policy_(threads) {}

double ThreadGovernor::reduced_seconds() const {
  if (policy_.threads() < policy_.requested())
    return reduced_ + seconds(Clock::now() - reduced_since_);
  return reduced_;
}

void ThreadGovernor::check() {
  const Clock::time_point now = Clock::now();
  if (!started_) {
    started_ = true;
    start_ = window_start_ = now;
    cpu_start_ = process_cpu_seconds();
    next_check_ = cycles_ + check_every_;
    return;
  }
  const double wall = seconds(now - window_start_);
  next_check_ = cycles_ + check_every_;
  if (wall < kWindow) {
    // Read the clock about twenty times a window, whatever a cycle costs.
    if (wall < 0.05 * kWindow)
      check_every_ = std::min(check_every_ * 2, 1L << 20);
    return;
  }
  const double cpu = process_cpu_seconds();
  const int before = policy_.threads();
  const int after = policy_.on_window((cpu - cpu_start_) / (wall * before), seconds(now - start_));
  window_start_ = now;
  cpu_start_ = cpu;
  if (after == before)
    return;
  if (after < before)
    reduced_since_ = now;
  else
    reduced_ += seconds(now - reduced_since_);
#ifdef _OPENMP
  omp_set_num_threads(after);
#endif
}

}  // namespace plyform::engine
