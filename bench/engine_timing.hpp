#pragma once
// Shared by the timed engine benchmarks: run a model for a number of cycles with outputs off
// and return the element-cycles per second the engine reports.

#include <cstdio>
#include <cstdlib>

#include "plyform/engine/solver.hpp"

namespace plyform::bench {

struct NullSink : engine::OutputSink {
  void state(const engine::Snapshot&) override {}
  void glstat(const engine::Energies&) override {}
  void nodout(const engine::Snapshot&) override {}
};

inline double element_cycles_per_second(const core::Model& m, long cycles, int threads) {
  core::Model run = m;
  run.controls.end_cycle = cycles;
  NullSink sink;
  engine::SolverOptions o;
  o.threads = threads;
  const engine::RunResult r = engine::run(run, sink, o);
  if (!r.ok) {
    std::fprintf(stderr, "run failed: %s\n", r.error.c_str());
    std::exit(1);
  }
  if (r.thread_reductions > 0) {
    // The thread governor saw the cores shared and ran part of the benchmark on one thread:
    // the figure is not the requested thread count's.
    std::fprintf(stderr, "note: %d thread(s) requested, 1 thread for %.3g of %.3g s (%d time%s)\n",
                 threads, r.reduced_thread_seconds, r.wall_seconds, r.thread_reductions,
                 r.thread_reductions == 1 ? "" : "s");
  }
  return r.element_cycles_per_second;
}

}  // namespace plyform::bench
