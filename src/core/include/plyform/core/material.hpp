#pragma once
// Runtime material parameters (consistent units). One struct per law; a block of elements
// carries one, dispatched once per block.

#include <variant>

namespace plyform::core {

/// *MAT_ELASTIC (001): isotropic, hypoelastic with the Jaumann rate for large deformation.
struct ElasticMaterial {
  double density = 0.0;
  double young = 0.0;
  double poisson = 0.0;
};

/// *MAT_MOONEY-RIVLIN_RUBBER (027), LS-DYNA's compressible form:
/// W = A (I1 - 3) + B (I2 - 3) + C (III^-2 - 1) + D (III - 1)^2,
/// C = A/2 + B, D = (A (5 nu - 2) + B (11 nu - 5)) / (2 (1 - 2 nu)).
struct MooneyRivlinMaterial {
  double density = 0.0;
  double poisson = 0.0;
  double a = 0.0;
  double b = 0.0;
};

using Material = std::variant<ElasticMaterial, MooneyRivlinMaterial>;

/// Density of any material.
[[nodiscard]] double density(const Material& m);
/// Small-strain bulk and shear moduli (for the time step and hourglass scaling).
[[nodiscard]] double bulk_modulus(const Material& m);
[[nodiscard]] double shear_modulus(const Material& m);

}  // namespace plyform::core
