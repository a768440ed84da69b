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
  return r.element_cycles_per_second;
}

}  // namespace plyform::bench
