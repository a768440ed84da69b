#pragma once
// The kinematics of a pass at the current positions: each slave node's segment, gap, slip,
// frame, penalty and effective mass for the law, and the first half of the step's work and of
// the surface book.

#include <vector>

#include "pass_runtime.hpp"

namespace plyform::contact {

/// Geometry and law inputs of every slave node of a pass at the current positions (dt 0: the
/// measure at t = 0, before any step).
void measure(PassRuntime& pr, double dt, const double* packed, const double* temperature,
             const std::vector<double>& mass, const unsigned char* rigid, const Rotations& rot);
/// measure()'s two stages. The surfaces' normals and folds, whole on every rank:
void measure_surfaces(PassRuntime& pr, double dt, const double* packed);
/// and the slave nodes' kinematics, over several ranks each rank's own (pr.mine).
void measure_slaves(PassRuntime& pr, double dt, const double* packed, const double* temperature,
                    const std::vector<double>& mass, const unsigned char* rigid,
                    const Rotations& rot);

}  // namespace plyform::contact
