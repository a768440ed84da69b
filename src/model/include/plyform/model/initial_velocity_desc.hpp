#pragma once

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// *INITIAL_VELOCITY_GENERATION: initial translational and angular velocity of a part, part
/// set or node set. v = (VX, VY, VZ) + OMEGA n x (x - xc), n = (NX, NY, NZ) normalised.
struct InitialVelocityGenerationDesc {
  int target_id = 0;   ///< ID: part set (STYP 1), part (STYP 2) or node set (STYP 3); 0 = all
  int styp = 0;        ///< STYP: 1 part set, 2 part, 3 node set
  double omega = 0.0;  ///< OMEGA: angular velocity about the axis, radians / time
  double vx = 0.0;     ///< VX, length / time
  double vy = 0.0;     ///< VY
  double vz = 0.0;     ///< VZ
  int ivatn = 0;       ///< IVATN: 0 slave nodes of rigid bodies ignored, 1 included
  int icid = 0;        ///< ICID: must be 0 (local systems are not supported yet)
  double xc = 0.0;     ///< XC YC ZC: a point on the rotation axis, length units
  double yc = 0.0;
  double zc = 0.0;
  double nx = 0.0;  ///< NX NY NZ: direction of the rotation axis
  double ny = 0.0;
  double nz = 0.0;
  int phase = 0;         ///< PHASE: 0 at t = 0 (1, after dynamic relaxation, is not supported)
  int irigid = 0;        ///< IRIGID, as written
  SourceLocation where;  ///< the line of card 1
};

/// *INITIAL_VELOCITY_NODE: one node's translational and angular velocity at t = 0 (it replaces
/// what an *INITIAL_VELOCITY_GENERATION gave the node).
struct InitialVelocityNodeDesc {
  int node_id = 0;                         ///< NID
  double vx = 0.0, vy = 0.0, vz = 0.0;     ///< VX VY VZ, length / time
  double vxr = 0.0, vyr = 0.0, vzr = 0.0;  ///< VXR VYR VZR, radians / time (shell nodes)
  SourceLocation where;
};

}  // namespace plyform::model
