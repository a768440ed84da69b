#pragma once
// The per-pass timing table `plyform run` prints at its end (engine/pass_timing.hpp).

#include <ostream>

#include "plyform/engine/pass_timing.hpp"

namespace plyform::app {

/// The passes that took at least 0.1 % of the loop, one line each (group, pass, seconds,
/// share), then the count and share of the smaller ones (all are in summary.json).
void print_timing(std::ostream& out, const engine::PassTiming& timing);

}  // namespace plyform::app
