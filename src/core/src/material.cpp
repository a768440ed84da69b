#include "plyform/core/material.hpp"

#include <algorithm>

namespace plyform::core {

namespace {

// Small-strain moduli of each law (consistent units, e.g. MPa).
struct Moduli {
  double bulk;
  double shear;
};

// *MAT_ELASTIC: K = E / (3 (1 - 2 nu)), G = E / (2 (1 + nu)).
Moduli moduli(const ElasticMaterial& m) {
  return {m.young / (3.0 * (1.0 - 2.0 * m.poisson)), m.young / (2.0 * (1.0 + m.poisson))};
}

// *MAT_MOONEY-RIVLIN_RUBBER: linearising W at F = I gives G = 2 (A + B) and, with LS-DYNA's
// D(nu), K = 28 A / 3 + 64 B / 3 + 8 D = 2 G (1 + nu) / (3 (1 - 2 nu)) (see docs/materials.md).
Moduli moduli(const MooneyRivlinMaterial& m) {
  const double g = 2.0 * (m.a + m.b);
  return {2.0 * g * (1.0 + m.poisson) / (3.0 * (1.0 - 2.0 * m.poisson)), g};
}

Moduli isotropic(double young, double poisson) {
  return {young / (3.0 * (1.0 - 2.0 * poisson)), young / (2.0 * (1.0 + poisson))};
}
Moduli moduli(const PiecewiseLinearPlasticity& m) {
  return isotropic(m.young, m.poisson);
}
Moduli moduli(const PowerLawPlasticity& m) {
  return isotropic(m.young, m.poisson);
}
Moduli moduli(const RigidMaterial& m) {
  return isotropic(m.young, m.poisson);
}
// Orthotropic: the stiffest direction bounds the wave speed (time step); the largest shear
// modulus for hourglass scaling.
Moduli moduli(const OrthotropicElasticMaterial& m) {
  const double e = std::max(m.ea, std::max(m.eb, m.ec));
  const double g = std::max(m.gab, std::max(m.gbc, m.gca));
  const double nu = std::max(m.prba, std::max(m.prca, m.prcb));
  return {e / (3.0 * (1.0 - 2.0 * std::min(nu, 0.45))), g};
}

}  // namespace

double density(const Material& m) {
  return std::visit([](const auto& mat) { return mat.density; }, m);
}

double bulk_modulus(const Material& m) {
  return std::visit([](const auto& mat) { return moduli(mat).bulk; }, m);
}

double shear_modulus(const Material& m) {
  return std::visit([](const auto& mat) { return moduli(mat).shear; }, m);
}

}  // namespace plyform::core
