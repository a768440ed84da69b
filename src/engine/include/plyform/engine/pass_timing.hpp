#pragma once
// Where a run's wall time went, pass by pass, as LS-DYNA's and OpenRadioss's timing tables
// say it: always measured (a steady-clock read at each pass of a cycle, one per element work
// item on each thread, four per contact pass), reported at the end of `plyform run` and in
// summary.json ("timing").

#include <string>
#include <vector>

namespace plyform::engine {

/// One line of the table: the group ("elements", "ranks", "contact", "thermal", "nodes", "outputs",
/// "other") and the pass within it, with its wall seconds over this process's time loop.
struct PassTime {
  std::string group;
  std::string name;
  double seconds = 0.0;
};

/// The table of a run: the time loop's wall seconds, and the passes in the cycle's order; their
/// seconds sum to loop_seconds (the last line, "other", is what no pass took: the loop's own
/// checks and the threads' start-up between passes).
struct PassTiming {
  double loop_seconds = 0.0;
  std::vector<PassTime> passes;
};

}  // namespace plyform::engine
