#pragma once

#include <array>
#include <string>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// Whether a boundary condition or load names one node (_NODE) or a node set (_SET).
enum class NodeTarget { kNode, kSet };

/// One card of *BOUNDARY_SPC_NODE / *BOUNDARY_SPC_SET (_ID): fixed degrees of freedom.
struct BoundarySpcDesc {
  NodeTarget target = NodeTarget::kNode;
  int target_id = 0;    ///< NID or NSID
  int id = 0;           ///< ID of the _ID option (0 without it)
  std::string heading;  ///< HEADING of the _ID option
  /// CID: 0 global axes, else the *DEFINE_COORDINATE_SYSTEM / _VECTOR whose axes the DOF
  /// flags name.
  int cid = 0;
  /// DOFX DOFY DOFZ DOFRX DOFRY DOFRZ: true = fixed (along or about the axes of CID).
  std::array<bool, 6> fixed{};
  SourceLocation where;  ///< the card line
};

/// One card of *BOUNDARY_PRESCRIBED_MOTION_NODE / _SET (_ID).
struct PrescribedMotionDesc {
  NodeTarget target = NodeTarget::kNode;
  int target_id = 0;    ///< NID or NSID
  int id = 0;           ///< ID of the _ID option (0 without it)
  std::string heading;  ///< HEADING of the _ID option
  /// DOF, LS-DYNA's code: 1, 2, 3 = global x, y, z translation; 9, 10, 11 = the node turns
  /// about an axis parallel to global x, y, z through (OFFSET1, OFFSET2).
  int dof = 0;
  int vad = 0;            ///< VAD: 0 velocity, 1 acceleration, 2 displacement
  int curve_id = 0;       ///< LCID: the curve of the motion against time
  double scale = 1.0;     ///< SF: ordinate scale factor of the curve
  int vid = 0;            ///< VID: vector id (only DOF 4/8, not supported): must be 0
  double death = 1.0e28;  ///< DEATH: time the motion ends, time units
  double birth = 0.0;     ///< BIRTH: time the motion starts, time units
  /// Card 2 (read for DOF 9-11 only): the axis's coordinates across it, (y, z) for DOF 9,
  /// (z, x) for 10, (x, y) for 11.
  double offset1 = 0.0;
  double offset2 = 0.0;
  SourceLocation where;  ///< the card line (card 1)
};

/// One card of *BOUNDARY_PRESCRIBED_MOTION_RIGID (_ID): the motion of a rigid body (a part
/// whose material is *MAT_RIGID), at its centre of mass.
struct PrescribedMotionRigidDesc {
  int part_id = 0;      ///< PID: the rigid part
  int id = 0;           ///< ID of the _ID option (0 without it)
  std::string heading;  ///< HEADING of the _ID option
  /// DOF, LS-DYNA's code: 1, 2, 3 = translation along global x, y, z; 5, 6, 7 = rotation about
  /// global x, y, z (through the centre of mass).
  int dof = 0;
  int vad = 0;            ///< VAD: 0 velocity, 1 acceleration, 2 displacement
  int curve_id = 0;       ///< LCID: the curve of the motion against time
  double scale = 1.0;     ///< SF: ordinate scale factor of the curve
  int vid = 0;            ///< VID: vector or coordinate system id; must be 0
  double death = 1.0e28;  ///< DEATH: time the motion ends, time units
  double birth = 0.0;     ///< BIRTH: time the motion starts, time units
  SourceLocation where;   ///< the card line
};

}  // namespace plyform::model
