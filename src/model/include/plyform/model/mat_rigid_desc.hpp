#pragma once

#include <array>
#include <string>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// *MAT_RIGID (*MAT_020): the elements of a part with this material form one rigid body.
/// E and PR only set contact stiffness; RO gives the body's mass and inertia.
struct MatRigidDesc {
  int id = 0;                   ///< MID
  std::string title;            ///< from the _TITLE option; empty otherwise
  double density = 0.0;         ///< RO, mass / length^3
  double youngs_modulus = 0.0;  ///< E, stress (for contact)
  double poisson_ratio = 0.0;   ///< PR (for contact)
  double n = 0.0;               ///< N: MADYMO coupling; must be 0 (not supported)
  double couple = 0.0;          ///< COUPLE: MADYMO/CAL3D coupling option; must be 0 (not supported)
  double m = 0.0;               ///< M: MADYMO/CAL3D system number; must be 0 (not supported)
  std::string alias;            ///< ALIAS: VDA surface name, as written
  /// CMO (card 2): constraint option, LS-DYNA's code: 0 none, 1 global constraints CON1/CON2,
  /// -1 local (CON1 = coordinate system, CON2 = SPC flags), +-2 as +-1 about a point. As
  /// written: the build step decides what it honours.
  int cmo = 0;
  /// CON1: CMO > 0: translations fixed, 0 none, 1 x, 2 y, 3 z, 4 x+y, 5 y+z, 6 z+x, 7 all;
  /// CMO < 0: a coordinate system id.
  int con1 = 0;
  /// CON2: CMO > 0: rotations fixed (codes as CON1); CMO < 0: SPC flags "xyzXYZ" as a
  /// six-digit number of 0s and 1s.
  int con2 = 0;
  int spcnid = 0;               ///< SPCNID: node of the constraint point (|CMO| = 2), as written
  std::array<double, 3> spc{};  ///< XSPC YSPC ZSPC: constraint point (|CMO| = 2), as written
  /// Card 3 (optional): LCO (a coordinate system id, when A2..V3 are 0) or A1, then A2 A3 and
  /// V1 V2 V3: the local output axes of the body, as written.
  std::array<double, 3> a{};
  std::array<double, 3> v{};
  SourceLocation where;  ///< the line of card 1
};

}  // namespace plyform::model
