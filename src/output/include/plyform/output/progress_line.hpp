#pragma once
// The progress line of `plyform run` on a terminal: one line rewritten in place with the
// simulated time, cycle, time step, wall time and estimated time left.

#include <cstddef>
#include <ostream>

namespace plyform::output {

/// True when standard output is a terminal (isatty).
[[nodiscard]] bool stdout_is_terminal();

/// Rewrites one line of `out` (carriage return, padded to clear the previous text) at most
/// every `min_interval_seconds` of wall time. Does nothing when not enabled.
class ProgressLine {
 public:
  ProgressLine(std::ostream& out, bool enabled, double min_interval_seconds = 0.2);

  /// `time`, `end_time`, `dt` in the model time unit; `wall_seconds` since the run started.
  /// The ETA comes from the rate of simulated time over wall time since the first update.
  void update(double time, double end_time, long cycle, double dt, double wall_seconds);
  /// Shows the last state given to update() (even if throttled) and ends the line.
  void finish();

  [[nodiscard]] bool enabled() const { return enabled_; }

 private:
  void draw();

  std::ostream& out_;
  bool enabled_;
  double min_interval_;
  bool has_state_ = false;
  bool drawn_since_update_ = false;
  bool started_ = false;
  double first_time_ = 0.0, first_wall_ = 0.0;
  double last_draw_wall_ = 0.0;
  double time_ = 0.0, end_time_ = 0.0, dt_ = 0.0, wall_ = 0.0;
  long cycle_ = 0;
  std::size_t last_length_ = 0;
};

}  // namespace plyform::output
