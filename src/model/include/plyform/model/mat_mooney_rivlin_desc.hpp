#pragma once

#include <string>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// *MAT_MOONEY-RIVLIN_RUBBER (*MAT_027): W = A (I1 - 3) + B (I2 - 3) + volumetric terms
/// from PR. Only constants given directly are supported (A or B non-zero, LCID1 = 0, REF = 0).
struct MatMooneyRivlinDesc {
  int id = 0;                  ///< MID
  std::string title;           ///< from the _TITLE option; empty otherwise
  double density = 0.0;        ///< RO, mass / length^3
  double poisson_ratio = 0.0;  ///< PR, in [0, 0.5) (about 0.49 and above for rubber)
  double a = 0.0;              ///< A, stress units
  double b = 0.0;              ///< B, stress units
  double ref = 0.0;            ///< REF (0: no reference geometry), must be 0
  double sgl = 0.0;            ///< SGL: specimen gauge length (curve fit only), as written
  double sw = 0.0;             ///< SW: specimen width (curve fit only), as written
  double st = 0.0;             ///< ST: specimen thickness (curve fit only), as written
  int lcid1 = 0;               ///< LCID1: force-deflection curve for a fit, must be 0
  double tbhys = 0.0;          ///< TBHYS, as written
  SourceLocation where;        ///< the line of card 1
};

}  // namespace plyform::model
