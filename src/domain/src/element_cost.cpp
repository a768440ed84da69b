// Per-element cost for the decomposition's weights, in units of a Belytschko-Tsay shell with NIP 5
// and J2 plasticity. The figures are this project's measurements on its 2-core machine
// (docs/speed.md, docs/parallel.md): BT NIP 5 J2 about 7.4 M element-cycles/s on one core,
// ELFORM 16 2.6 to 2.7 times a BT element, hex8 ELFORM 1 about 10 M and ELFORM 2 about 1.5 M
// (elastic), a contact slave node 1.2 to 1.5 BT elements a pass. A split only needs the ratios
// to within some 20 percent.

#include <variant>

#include "plyform/domain/decomposition.hpp"

namespace plyform::domain {

namespace {

// The law's cost at a point relative to J2's plane-stress return: an elastic update is cheaper,
// the laws with temperature tables and the woven ply (three families and their shear) dearer.
double law_factor(const core::Material& m) {
  if (std::holds_alternative<core::RigidMaterial>(m))
    return 0.0;
  if (std::holds_alternative<core::ElasticMaterial>(m) ||
      std::holds_alternative<core::OrthotropicElasticMaterial>(m) ||
      std::holds_alternative<core::MooneyRivlinMaterial>(m))
    return 0.6;
  if (std::holds_alternative<core::ElasticPlasticThermal>(m) ||
      std::holds_alternative<core::ReinforcedThermoplastic>(m) ||
      std::holds_alternative<core::Barlat89Plastic>(m) ||
      std::holds_alternative<core::Hill3RPlastic>(m))
    return 1.4;
  return 1.0;
}

}  // namespace

double shell_cost(const core::Model& model, const core::ShellBlock& block) {
  const double law = law_factor(model.materials[static_cast<std::size_t>(block.material)]);
  if (law == 0.0)
    return 0.0;
  // The frame, resultants and scatter (about 0.3 of a NIP 5 element) plus the points' share.
  const double bt = 0.3 + 0.14 * law * block.nip;
  return block.formulation == core::ShellFormulation::fully_integrated ? 2.65 * bt : bt;
}

double solid_cost(const core::Model& model, const core::SolidBlock& block) {
  const double law = law_factor(model.materials[static_cast<std::size_t>(block.material)]);
  if (law == 0.0)
    return 0.0;
  // ELFORM 1: one point (elastic about 0.7 BT element); ELFORM 2: eight points.
  return block.formulation == core::SolidFormulation::one_point ? 0.5 + 0.35 * law
                                                                : 0.9 + 6.0 * law;
}

}  // namespace plyform::domain
