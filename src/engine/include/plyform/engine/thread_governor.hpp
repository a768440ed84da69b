#pragma once
// Keeps a run at its fair share of a shared machine.
//
// OpenMP's worker threads spin at the end of each parallel region and at barriers, waiting for
// the slowest of the team. When another run's threads share the cores, the thread that is
// waited for is often descheduled, and each of the cycle's parallel regions then costs a
// scheduler time slice: two 2-thread runs on a 2-core machine each ran 10 times slower than
// alone (issue 11). The governor watches the process's CPU time against the wall clock. A run
// whose threads get much less CPU than they ask for is sharing its cores; it drops to one
// thread (the results do not depend on the thread count: every sum is deterministic). After a
// while it probes its full count again, and backs off longer while the sharing persists.

#include <chrono>

namespace plyform::engine {

/// The decision, apart from the clocks (tested alone): fed one measurement window at a time.
class ThreadPolicy {
 public:
  /// CPU per thread below which the cores are taken to be shared. Alone, the spinning workers
  /// keep a team near 1 (serial stretches shorter than the spin count still count as CPU); two
  /// teams on the same cores get about 1/2 each, a team beside a one-thread run about 2/3.
  static constexpr double kShared = 0.75;
  static constexpr double kFirstBackoff = 2.0;  ///< [s] on one thread before the first probe
  static constexpr double kMaxBackoff = 32.0;   ///< [s]

  explicit ThreadPolicy(int requested);
  /// A window ending at `now` [s] in which the process used `cpu_per_thread` seconds of CPU per
  /// wall second and thread; returns the thread count for the next window.
  int on_window(double cpu_per_thread, double now);
  [[nodiscard]] int threads() const { return current_; }
  [[nodiscard]] int requested() const { return requested_; }
  [[nodiscard]] int reductions() const { return reductions_; }

 private:
  int requested_;
  int current_;
  int low_windows_ = 0;  // consecutive windows at the full count with too little CPU
  double backoff_ = kFirstBackoff;
  double probe_at_ = 0.0;
  int reductions_ = 0;
};

/// The policy on the real clocks; tick() once per cycle.
class ThreadGovernor {
 public:
  /// `threads`: the count the user asked for (the most the governor uses).
  explicit ThreadGovernor(int threads);

  /// Reads the wall clock every few cycles; at the end of each window, the CPU clock too.
  void tick() {
    if (policy_.requested() > 1 && ++cycles_ >= next_check_)
      check();
  }

  [[nodiscard]] int threads() const { return policy_.threads(); }
  /// Times the run dropped to one thread, and the wall seconds it ran on fewer than requested.
  [[nodiscard]] int reductions() const { return policy_.reductions(); }
  [[nodiscard]] double reduced_seconds() const;

 private:
  void check();

  using Clock = std::chrono::steady_clock;
  ThreadPolicy policy_;
  long cycles_ = 0, next_check_ = 16, check_every_ = 16;
  Clock::time_point start_, window_start_, reduced_since_;
  double cpu_start_ = 0.0;
  double reduced_ = 0.0;  // seconds on fewer threads, up to the last return to the full count
  bool started_ = false;
};

}  // namespace plyform::engine
