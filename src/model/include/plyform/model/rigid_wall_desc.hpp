#pragma once

#include <array>
#include <string>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// *RIGIDWALL_PLANAR with its options _FINITE, _MOVING, _FORCES and _ID: a plane that the slave
/// nodes cannot cross, on the side its normal points to (from the tail XT, YT, ZT on the wall
/// to the head XH, YH, ZH). Constraint method: a node that would cross it is stopped on it.
struct RigidWallDesc {
  int id = 0;           ///< ID of the _ID option (0 without it)
  std::string heading;  ///< HEADING of the _ID option
  int nsid = 0;         ///< NSID: slave node set (0: every node)
  int nsidex = 0;       ///< NSIDEX: node set left out (0: none)
  int boxid = 0;        ///< BOXID: must be 0 (*DEFINE_BOX is not read)
  double offset = 0.0;  ///< OFFSET: > 0 keeps only the nodes within this distance at t = 0
  double birth = 0.0;   ///< BIRTH
  double death = 1e20;  ///< DEATH
  double rwksf = 1.0;   ///< RWKSF: the penalty form's stiffness scale (the constraint ignores it)
  std::array<double, 3> tail{};  ///< XT, YT, ZT: a point of the wall
  std::array<double, 3> head{};  ///< XH, YH, ZH: the normal's head
  double fric = 0.0;    ///< FRIC: 0 frictionless, 1 no sliding, between: Coulomb coefficient
  double wvel = 0.0;    ///< WVEL: welding's critical velocity (FRIC 2, 3: not supported)
  bool finite = false;  ///< _FINITE: a rectangle
  std::array<double, 3> edge{};  ///< XHEV, YHEV, ZHEV: head of the edge vector l from the tail
  double length_l = 0.0;         ///< LENL: the rectangle's length along l
  double length_m = 0.0;         ///< LENM: its length along m = n x l
  bool moving = false;           ///< _MOVING: a wall of mass MASS moving along its normal
  double mass = 0.0;             ///< MASS
  double v0 = 0.0;               ///< V0: initial velocity along the normal
  bool forces = false;           ///< _FORCES: its card was given (rwforc.csv is always written)
  int soft = 0;                  ///< SOFT: must be 0
  int ssid = 0;                  ///< SSID: must be 0 (the force per segment is not written)
  std::array<int, 4> display{};  ///< N1..N4: nodes that move with the wall (0: none)
  std::string keyword;           ///< as written, for messages
  SourceLocation where;          ///< the keyword line
  SourceLocation card1;          ///< card 1 (NSID ...)
  SourceLocation card2;          ///< card 2 (XT ...)
  SourceLocation forces_card;    ///< the _FORCES card (N1..N4)
};

}  // namespace plyform::model
