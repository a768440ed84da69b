#include "timing_report.hpp"

#include <algorithm>
#include <string>

#include <fmt/format.h>
#include <fmt/ostream.h>

namespace plyform::app {

void print_timing(std::ostream& out, const engine::PassTiming& timing) {
  if (!(timing.loop_seconds > 0.0) || timing.passes.empty())
    return;
  const double total = timing.loop_seconds;
  constexpr double kShown = 1e-3;
  std::size_t width = 0;
  for (const engine::PassTime& p : timing.passes)
    width = std::max(width, p.group.size() + 2 + p.name.size());
  fmt::print(out, "timing: the time loop's {:.4g} s wall, pass by pass:\n", total);
  std::size_t small = 0;
  double small_seconds = 0.0;
  for (const engine::PassTime& p : timing.passes) {
    if (p.seconds < kShown * total) {
      ++small;
      small_seconds += p.seconds;
      continue;
    }
    fmt::print(out, "  {:<{}} {:>9.3f} s {:>6.2f} %\n", p.group + ": " + p.name, width, p.seconds,
               100.0 * p.seconds / total);
  }
  if (small > 0) {
    fmt::print(out,
               "  ({} more pass{} under 0.1 % each, {:.2f} % together: summary.json has all)\n",
               small, small == 1 ? "" : "es", 100.0 * small_seconds / total);
  }
}

}  // namespace plyform::app
