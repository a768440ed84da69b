#pragma once
// What of a pass's surfaces this cycle's kinematics read, found before the normals, folds and
// centroids are computed, so that only those are (surface_normals.hpp). A slave node's
// kinematics read, of the master: its segment of last cycle, that segment's neighbours (the
// look across a valley) and its candidates; of each such segment the normal and its corners'
// nodal normals (each the mean of the faces around the corner); the fold of its segment and the
// centroids of that segment and its neighbours. Of the slave side: its own normal (the mean of
// its faces') when it has a segment or a candidate. A node with neither reads nothing. Far from
// the tools most of a blank's nodes are such nodes, and most of a tool's segments are read by
// none: on a 100 x 100 plate under a dome punch the surfaces' passes were some 14 % of a run.
// The values computed are the same numbers as before; the others are not read (and keep older
// values, which the checkpoint holds like the rest).

#include "pass_runtime.hpp"

namespace plyform::contact {

/// Fills pr.reads for this cycle, for the slave nodes this rank handles (pr.mine), and for
/// every slave node the master's normals where the scatter reads them (`spins`: the nodes have
/// rotations, whose couples an offset master's corners carry). Where the lists would hold most
/// of a side (the master's segments, the slave nodes), that side is computed whole
/// (`all_master`, `all_slaves`): the lists cost about as much as what they would save; when both
/// are, for the next 64 cycles without a look.
void find_surface_reads(PassRuntime& pr, bool spins);

}  // namespace plyform::contact
