#pragma once

#include <string>
#include <vector>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// *MAT_PIECEWISE_LINEAR_PLASTICITY (*MAT_024): isotropic elasto-plasticity (von Mises) with
/// isotropic hardening given by a curve, an 8-point table, or bilinearly by SIGY and ETAN.
/// Rate effects (C, P, LCSR) and failure curves (LCF) are rejected by the reader.
struct MatPiecewiseLinearPlasticityDesc {
  int id = 0;                    ///< MID
  std::string title;             ///< from the _TITLE option; empty otherwise
  double density = 0.0;          ///< RO, mass / length^3
  double youngs_modulus = 0.0;   ///< E, stress
  double poisson_ratio = 0.0;    ///< PR
  double yield_stress = 0.0;     ///< SIGY, stress (ignored when LCSS or the table is given)
  double tangent_modulus = 0.0;  ///< ETAN, stress (ignored when LCSS or the table is given)
  /// FAIL: effective plastic strain at which the element is deleted (blank: 1e21, never; 0:
  /// failure not considered). Kept as written: the build step decides.
  double fail = 1.0e21;
  double tdel = 0.0;  ///< TDEL: minimum time step for element deletion, time, as written
  double c = 0.0;     ///< C: Cowper-Symonds rate parameter (0: no rate effect)
  double p = 0.0;     ///< P: Cowper-Symonds rate exponent (0: no rate effect)
  /// LCSS: id of a *DEFINE_CURVE of yield stress (ordinate) against effective plastic strain
  /// (abscissa); 0 = none. When set, EPS/ES, SIGY and ETAN are ignored (as in LS-DYNA).
  int lcss = 0;
  int lcsr = 0;     ///< LCSR: strain rate scaling curve; must be 0 (not supported yet)
  double vp = 0.0;  ///< VP: rate formulation (0 with rate effects), as written
  int lcf = 0;      ///< LCF: failure strain curve; must be 0 (not supported yet)
  /// EPS1..EPSn and ES1..ESn: the optional table of effective plastic strain and yield stress
  /// (n = 2..8: up to the last non-zero ES; both empty when not given). Strains increase.
  std::vector<double> eps;
  std::vector<double> es;
  SourceLocation where;  ///< the line of card 1
};

/// *MAT_POWER_LAW_PLASTICITY (*MAT_018): isotropic plasticity with the hardening
/// sigma_y = K (eps_yp + eps_p)^N. Rate effects (SRC, SRP) are rejected by the reader.
struct MatPowerLawPlasticityDesc {
  int id = 0;                   ///< MID
  std::string title;            ///< from the _TITLE option; empty otherwise
  double density = 0.0;         ///< RO, mass / length^3
  double youngs_modulus = 0.0;  ///< E, stress
  double poisson_ratio = 0.0;   ///< PR
  double k = 0.0;               ///< K: strength coefficient, stress
  double n = 0.0;               ///< N: hardening exponent
  double src = 0.0;             ///< SRC: Cowper-Symonds C (0: no rate effect)
  double srp = 0.0;             ///< SRP: Cowper-Symonds P (0: no rate effect)
  /// SIGY (card 2): initial yield. LS-DYNA: below 0.02 it is the strain to yield eps_yp
  /// itself; from 0.02 on it is a yield stress and eps_yp = (SIGY / K)^(1/N). 0: eps_yp from
  /// the elastic limit. As written.
  double sigy = 0.0;
  double vp = 0.0;       ///< VP (card 2): rate formulation (0 with rate effects), as written
  double epsf = 0.0;     ///< EPSF (card 2): plastic failure strain, as written (0: none)
  SourceLocation where;  ///< the line of card 1
};

}  // namespace plyform::model
