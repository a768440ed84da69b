#pragma once

#include <array>
#include <string>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// *MAT_ORTHOTROPIC_ELASTIC (*MAT_002): linear orthotropic elasticity in material axes a, b, c.
/// Material axes: AOPT 0 (from the element's nodes, rotated by the element's or this card's
/// BETA for shells) or 2 (global, from vectors a and d); the other AOPT are rejected.
struct MatOrthotropicElasticDesc {
  int id = 0;                 ///< MID
  std::string title;          ///< from the _TITLE option; empty otherwise
  double density = 0.0;       ///< RO, mass / length^3
  double ea = 0.0;            ///< EA: Young's modulus along a, stress
  double eb = 0.0;            ///< EB: Young's modulus along b, stress
  double ec = 0.0;            ///< EC: Young's modulus along c, stress
  double prba = 0.0;          ///< PRBA: Poisson's ratio nu_ba
  double prca = 0.0;          ///< PRCA: Poisson's ratio nu_ca
  double prcb = 0.0;          ///< PRCB: Poisson's ratio nu_cb
  double gab = 0.0;           ///< GAB: shear modulus ab, stress
  double gbc = 0.0;           ///< GBC: shear modulus bc, stress
  double gca = 0.0;           ///< GCA: shear modulus ca, stress
  int aopt = 0;               ///< AOPT: material axes option, 0 or 2
  double g = 0.0;             ///< G: frequency-independent damping modulus; must be 0
  double sigf = 0.0;          ///< SIGF: limit stress of that damping; must be 0
  std::array<double, 3> p{};  ///< XP YP ZP: point P (AOPT 1 and 4 only), as written
  std::array<double, 3> a{};  ///< A1 A2 A3: vector a (AOPT 2), global axes
  int macf = 1;               ///< MACF: axes change flag of bricks; 1 (no change) only
  std::array<double, 3> v{};  ///< V1 V2 V3: vector v (AOPT 3 and 4 only), as written
  std::array<double, 3> d{};  ///< D1 D2 D3: vector d (AOPT 2): with a, spans the a-b plane
  double beta = 0.0;          ///< BETA: material angle, degrees (AOPT 0 shells), as written
  double ref = 0.0;           ///< REF: reference geometry flag; must be 0
  SourceLocation where;       ///< the line of card 1
};

}  // namespace plyform::model
