#pragma once
// SIGINT and SIGTERM ask a run to stop after its cycle with a checkpoint; a second one ends the
// process at once, as does one outside a run.
//
// A handler may run on any thread whose mask lets the signal in, and while it runs it interrupts
// whatever that thread was doing. METIS (a re-split while running over several ranks) installs
// handlers of its own for SIGTERM during each call and jumps out of the call when one arrives:
// a SIGTERM that fell into a re-split was taken by METIS, the split failed on that rank alone
// and the run never stopped. So the signals are not handled at all: `watch_stop_signals`, first
// thing in main() (before MPI and OpenMP start their threads, which inherit the mask), blocks
// them in every thread, and a thread of its own waits for them (sigwait) and raises the stop
// flag. A process that did not call it (the tests that call the commands in-process) gets
// handlers instead.

#include <csignal>

namespace plyform::app {

/// Blocks SIGINT and SIGTERM in this and every later thread and starts the thread that takes
/// them. Call once, in main(), before any other thread starts.
void watch_stop_signals();

/// For the lifetime of a run: the first SIGINT or SIGTERM sets *flag (which starts at 0); the
/// second ends the process. Outside a run either ends the process.
class StopOnSignals {
 public:
  explicit StopOnSignals(volatile std::sig_atomic_t* flag);
  ~StopOnSignals();
  StopOnSignals(const StopOnSignals&) = delete;
  StopOnSignals& operator=(const StopOnSignals&) = delete;

 private:
  void (*int_)(int) = SIG_DFL;
  void (*term_)(int) = SIG_DFL;
};

}  // namespace plyform::app
