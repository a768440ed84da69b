#pragma once
// The raw measurements of the per-pass timing (plyform/engine/pass_timing.hpp) a run collects
// as it goes, and the table made of them at the end. Private to plyform_engine.

#include <array>
#include <cstddef>
#include <vector>

#include "plyform/contact/contact_set.hpp"
#include "plyform/core/model.hpp"
#include "plyform/engine/pass_timing.hpp"

namespace plyform::engine {

// The passes the engine times itself, in the cycle's order.
enum class Pass : std::size_t {
  positions,    // the nodes' displacements and the packed positions of the step
  loads,        // nodal loads and prescribed temperatures
  elements,     // the element loop (all blocks; split by block below)
  exchange,     // over several MPI ranks: the nodes' and elements' values after the element loop
  thermal,      // the thermal step when due, and the check of the tables' ranges
  contact,      // every interface (split by interface and stage by the contact set)
  step_vote,    // the next step
  velocities,   // velocities, constraints, rigid bodies, the external work
  outputs,      // the output files, the progress line
  books,        // the energy books' check
  checkpoints,  // restart files
  count
};

struct PassClock {
  std::array<double, static_cast<std::size_t>(Pass::count)> seconds{};
  double heat_sources = 0.0;  // part of `thermal`: the contact links and the heat sources
  void add(Pass p, double s) { seconds[static_cast<std::size_t>(p)] += s; }
  [[nodiscard]] double at(Pass p) const { return seconds[static_cast<std::size_t>(p)]; }
};

// What the table is made of besides the clock: the threads' seconds in each block's element
// kernel (summed over the threads: the element loop's wall time is shared out in proportion),
// the contact set's stages, the thermal solves, and the loop's wall seconds.
struct TimingSources {
  std::vector<double> solid_block_seconds, shell_block_seconds;
  std::vector<contact::InterfaceTiming> contact;
  double contact_exchange_seconds = 0.0;  // over several ranks: the slave nodes' forces
  double heat_solve_seconds = 0.0;
  double loop_seconds = 0.0;
};

PassTiming timing_table(const core::Model& model, const PassClock& clock,
                        const TimingSources& sources);

}  // namespace plyform::engine
