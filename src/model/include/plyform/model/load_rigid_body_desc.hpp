#pragma once

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// One card of *LOAD_RIGID_BODY: a force or moment of a curve on a rigid body (a part whose
/// material is *MAT_RIGID), at its centre of mass.
struct LoadRigidBodyDesc {
  int part_id = 0;  ///< PID: the rigid part
  /// DOF, LS-DYNA's code: 1, 2, 3 = force along global x, y, z; 5, 6, 7 = moment about
  /// global x, y, z.
  int dof = 0;
  int curve_id = 0;    ///< LCID: the curve of the force or moment against time
  double scale = 1.0;  ///< SF: ordinate scale factor of the curve
  int cid = 0;         ///< CID: must be 0 (local systems are not supported yet)
  int m1 = 0;          ///< M1 M2 M3: nodes of a follower force (DOF 4/8 only), as written
  int m2 = 0;
  int m3 = 0;
  SourceLocation where;  ///< the card line
};

}  // namespace plyform::model
