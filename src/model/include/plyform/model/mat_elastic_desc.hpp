#pragma once

#include <string>

#include "plyform/model/source_location.hpp"

namespace plyform::model {

/// *MAT_ELASTIC (*MAT_001): isotropic linear elasticity.
struct MatElasticDesc {
  int id = 0;                   ///< MID
  std::string title;            ///< from the _TITLE option; empty otherwise
  double density = 0.0;         ///< RO, mass / length^3
  double youngs_modulus = 0.0;  ///< E, stress units
  double poisson_ratio = 0.0;   ///< PR, in [-1, 0.5)
  double da = 0.0;              ///< DA: axial damping factor (beams), as written
  double db = 0.0;              ///< DB: bending damping factor (beams), as written
  double k = 0.0;               ///< K: bulk modulus (fluid option only), as written
  SourceLocation where;         ///< the line of card 1
};

}  // namespace plyform::model
