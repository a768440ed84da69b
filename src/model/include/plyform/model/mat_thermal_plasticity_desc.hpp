#pragma once
// Temperature-dependent mechanics: *MAT_ELASTIC_PLASTIC_THERMAL (*MAT_004) and
// *MAT_ADD_THERMAL_EXPANSION.

#include <string>
#include <vector>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// *MAT_ELASTIC_PLASTIC_THERMAL (*MAT_004): isotropic elasto-plasticity with bilinear isotropic
/// hardening whose constants are tabulated against temperature at 2..8 points T1 < T2 < ...
/// (LS-DYNA's cards 2-7; the table ends at the last point whose temperature was written).
/// Between the points every constant is linear in temperature; a temperature outside the
/// table stops the run, as in LS-DYNA. All vectors have the same length.
struct MatElasticPlasticThermalDesc {
  int id = 0;                       ///< MID
  std::string title;                ///< from the _TITLE option; empty otherwise
  double density = 0.0;             ///< RO, mass / length^3
  std::vector<double> temperature;  ///< T1..Tn, increasing
  std::vector<double> young;        ///< E1..En, stress, > 0
  std::vector<double> poisson;      ///< PR1..PRn
  std::vector<double> alpha;        ///< ALPHA1..ALPHAn, 1/temperature (the tangent coefficient)
  std::vector<double> sigy;         ///< SIGY1..SIGYn, stress, > 0
  std::vector<double> etan;         ///< ETAN1..ETANn, stress, 0 <= ETAN < E
  SourceLocation where;             ///< the line of card 1
};

/// *MAT_ADD_THERMAL_EXPANSION: an isotropic thermal expansion added to the material of part PID
/// (any law): the thermal strain rate alpha(T) dT/dt with alpha = MULT times the curve LCID
/// against temperature (LCID 0: alpha = MULT). The orthotropic option (LCIDY, LCIDZ) is
/// rejected by the reader.
struct MatAddThermalExpansionDesc {
  int pid = 0;           ///< PID: the part
  int lcid = 0;          ///< LCID: curve of alpha against temperature (0: constant MULT)
  double mult = 1.0;     ///< MULT: scale on the curve (blank: 1)
  SourceLocation where;  ///< the keyword's card
};

}  // namespace plyform::model
