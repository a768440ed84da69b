#pragma once

#include "plyform/model/boundary_desc.hpp"
#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// One card of *LOAD_NODE_POINT / *LOAD_NODE_SET: a concentrated nodal force of a curve.
struct LoadNodeDesc {
  NodeTarget target = NodeTarget::kNode;  ///< _POINT: one node; _SET: a node set
  int target_id = 0;                      ///< NID or NSID
  int dof = 0;                            ///< DOF: 1, 2, 3 = force in global x, y, z
  int curve_id = 0;                       ///< LCID: the curve of the force against time
  double scale = 1.0;                     ///< SF: ordinate scale factor of the curve
  int cid = 0;                            ///< CID: must be 0 (local systems are not supported yet)
  int m1 = 0;  ///< M1 M2 M3: nodes of a follower force (DOF 4/8 only), as written
  int m2 = 0;
  int m3 = 0;
  SourceLocation where;  ///< the card line
};

}  // namespace plyform::model
