#include "plyform/output/progress_line.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <iterator>
#include <string>

namespace plyform::output {
namespace {

/// "45s", "12m05s", "3h07m".
void append_duration(std::string& out, double seconds) {
  if (!std::isfinite(seconds) || seconds < 0.0) {
    out += "--";
    return;
  }
  const auto s = static_cast<long>(std::lround(seconds));
  if (s < 60) {
    fmt::format_to(std::back_inserter(out), "{}s", s);
  } else if (s < 3600) {
    fmt::format_to(std::back_inserter(out), "{}m{:02}s", s / 60, s % 60);
  } else {
    fmt::format_to(std::back_inserter(out), "{}h{:02}m", s / 3600, (s % 3600) / 60);
  }
}

}  // namespace

bool stdout_is_terminal() {
  return ::isatty(::fileno(stdout)) == 1;
}

ProgressLine::ProgressLine(std::ostream& out, bool enabled, double min_interval_seconds)
    : out_(out), enabled_(enabled), min_interval_(min_interval_seconds) {}

void ProgressLine::update(double time, double end_time, long cycle, double dt,
                          double wall_seconds) {
  if (!enabled_) {
    return;
  }
  if (!started_) {
    started_ = true;
    first_time_ = time;
    first_wall_ = wall_seconds;
  }
  time_ = time;
  end_time_ = end_time;
  cycle_ = cycle;
  dt_ = dt;
  wall_ = wall_seconds;
  has_state_ = true;
  drawn_since_update_ = false;
  if (last_length_ > 0 && wall_seconds - last_draw_wall_ < min_interval_) {
    return;
  }
  draw();
}

void ProgressLine::finish() {
  if (!enabled_) {
    return;
  }
  if (has_state_ && !drawn_since_update_) {
    draw();
  }
  if (last_length_ > 0) {
    out_ << '\n';
    out_.flush();
  }
  last_length_ = 0;
  has_state_ = false;
  started_ = false;
}

void ProgressLine::draw() {
  std::string line;
  const double percent = end_time_ > 0.0 ? 100.0 * time_ / end_time_ : 0.0;
  fmt::format_to(std::back_inserter(line),
                 "t {:.4e} / {:.4e} ({:5.1f}%)  cycle {}  dt {:.3e}  wall ", time_, end_time_,
                 percent, cycle_, dt_);
  append_duration(line, wall_);
  line += "  ETA ";
  const double simulated = time_ - first_time_;
  const double elapsed = wall_ - first_wall_;
  if (time_ >= end_time_) {
    append_duration(line, 0.0);
  } else if (simulated > 0.0 && elapsed > 0.0) {
    append_duration(line, (end_time_ - time_) * elapsed / simulated);
  } else {
    line += "--";
  }
  const std::size_t length = line.size();
  if (length < last_length_) {
    line.append(last_length_ - length, ' ');
  }
  out_ << '\r' << line;
  out_.flush();
  last_length_ = length;
  last_draw_wall_ = wall_;
  drawn_since_update_ = true;
}

}  // namespace plyform::output
