#pragma once
// *MAT_REINFORCED_THERMOPLASTIC (*MAT_249): a woven or unidirectional fibre ply in a
// thermoplastic matrix, for shells (LS-DYNA's cards 1-9, as written).

#include <array>
#include <string>
#include <vector>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// One fibre family (cards 4, 6, 8: IDFi ALPHi EFi LCEFi G23_i G31_i).
struct FibreFamilyDesc {
  int idf = 0;           ///< IDFi: the family's id for post-processing
  double alpha = 0.0;    ///< ALPHi: angle from the material axis a about the normal, degrees
  double ef = 0.0;       ///< EFi: the fibres' Young's modulus, stress (tension only)
  int lcef = 0;          ///< LCEFi: curve (or table over temperature) of fibre stress against
                         ///< fibre strain; replaces EFi when non-zero
  double g23 = 0.0;      ///< G23_i: transverse shear modulus orthogonal to the fibres, stress
  double g31 = 0.0;      ///< G31_i: transverse shear modulus along the fibres, stress
  SourceLocation where;  ///< the card's line
};

/// The in-plane shear between two neighbouring families (cards 5 and 7: Gij LCGij ALOCij GLOCij
/// METHij), between families 1 and 2 (card 5) and 2 and 3 (card 7).
struct FibreShearDesc {
  double g = 0.0;        ///< Gij: linear shear modulus, stress
  int lcg = 0;           ///< LCGij: curve (or table over temperature) of shear stress against
                         ///< the shear angle (radians); replaces Gij as the response when non-zero
  double aloc = 0.0;     ///< ALOCij: locking angle, radians (0: no locking)
  double gloc = 0.0;     ///< GLOCij: shear modulus past the locking angle, stress
  int meth = 0;          ///< METHij: 2 elastic curve, 3 elasto-plastic curve (of the shear angle)
  SourceLocation where;  ///< the card's line
};

struct MatReinforcedThermoplasticDesc {
  int id = 0;                 ///< MID
  std::string title;          ///< from the _TITLE option; empty otherwise
  double density = 0.0;       ///< RO, mass / length^3
  double em = 0.0;            ///< EM: the matrix's Young's modulus, stress
  int lcem = 0;               ///< LCEM: curve of EM against temperature (replaces EM when non-zero)
  double prm = 0.0;           ///< PRM: the matrix's Poisson's ratio
  int lcprm = 0;              ///< LCPRM: curve of PRM against temperature (replaces PRM)
  int lcsigy = 0;             ///< LCSIGY: the matrix's yield stress against effective plastic
                              ///< strain, a curve or a table over temperature (0: elastic matrix)
  double beta = 0.0;          ///< BETA: mixed hardening (0 kinematic, 1 isotropic)
  int nfib = 0;               ///< NFIB: number of fibre families, 1..3
  int aopt = 0;               ///< AOPT: material axes, 0, 2 or 3
  std::array<double, 3> p{};  ///< XP YP ZP (AOPT 1 and 4 only), as written
  std::array<double, 3> a{};  ///< A1 A2 A3: vector a (AOPT 2), global axes
  std::array<double, 3> v{};  ///< V1 V2 V3: vector v (AOPT 3), global axes
  std::array<double, 3> d{};  ///< D1 D2 D3: vector d (AOPT 2)
  double mangl = 0.0;         ///< MANGL: material angle about the normal, degrees (AOPT 0, 3)
  double thick = 0.0;         ///< THICK: fibre stress scaling by the thickness change; 0 only
  std::vector<FibreFamilyDesc> fibres;  ///< NFIB families, in order
  std::vector<FibreShearDesc> shears;   ///< NFIB - 1 pairs: (1, 2), then (2, 3)
  int postv = 0;                        ///< POSTV: extra post-processing variables, as written
  double ihis = 0.0;                    ///< IHIS: history initialisation flag; 0 only
  SourceLocation where;                 ///< the line of card 1
};

}  // namespace plyform::model
