#pragma once
// The search of a pass: each slave node's candidate segments (the bucket grid), and the pass's
// vote for the stable step.

#include <vector>

#include "pass_runtime.hpp"

namespace plyform::contact {

/// Candidates of every slave node within the segments' reach, the motion reference for the
/// next re-search, and the pass's step vote (its stiffest spring against its lightest mass).
void search(PassRuntime& pr, const double* packed, const std::vector<double>& mass,
            const unsigned char* rigid, const Rotations& rot, double tssfac);

}  // namespace plyform::contact
