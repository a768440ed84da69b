#pragma once
// The nodal normals of a pass's offset surfaces (the master's and the slave's, from the faces
// around each node, every cycle) and the folds of the master surface (where a node near a
// segment's edge looks across a valley).

#include "pass_runtime.hpp"

namespace plyform::contact {

/// What `folded` holds, in the builds that check invariants, for a segment this cycle's lists
/// left out (surface_reads.hpp): no reader may see it.
inline constexpr unsigned char kUnlistedFold = 2;

/// The master's nodal normals at t = 0 and the signs that turn each segment's normal to agree
/// with them; the slave's likewise.
void init_nodal_normals(PassRuntime& pr, const double* packed);
/// The master's segment and nodal normals at the current positions.
void update_master_normals(PassRuntime& pr, const double* packed);
/// The slave nodes' normals at the current positions.
void update_slave_normals(PassRuntime& pr, const double* packed);
/// Which segments have a neighbour out of their plane this cycle (PassRuntime::folded).
void update_folds(PassRuntime& pr, const double* packed);

}  // namespace plyform::contact
