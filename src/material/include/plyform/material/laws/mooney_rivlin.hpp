#pragma once
// *MAT_MOONEY-RIVLIN_RUBBER (027), LS-DYNA's compressible form, solids: the Cauchy stress from
// the deformation gradient (a total law). Derivation: docs/materials.md.

#include "plyform/material/laws/law_traits.hpp"

namespace plyform::material {

struct MooneyRivlinLaw {
  using Parameters = core::MooneyRivlinMaterial;
  static constexpr LawInfo info{"*MAT_MOONEY-RIVLIN_RUBBER", 27, "Mooney-Rivlin rubber"};
  static constexpr bool for_solids = true, for_shells = false;
  static constexpr bool needs_deformation_gradient = true, needs_material_axes = false;
  static constexpr std::array<std::string_view, 0> history{};
  static constexpr std::array<std::string_view, 1> results{"stress"};
  /// Linearising W at F = I: G = 2 (A + B) and, with LS-DYNA's D(nu),
  /// K = 28 A / 3 + 64 B / 3 + 8 D = 2 G (1 + nu) / (3 (1 - 2 nu)) (docs/materials.md).
  static const auto& cards(const model::ModelDesc& d) { return d.mooney_rivlin_materials; }
  static Parameters from_card(const model::MatMooneyRivlinDesc& c, const DeckCurve&) {
    return {c.density, c.poisson_ratio, c.a, c.b};
  }
  static Moduli moduli(const Parameters& m) {
    const double g = 2.0 * (m.a + m.b);
    return {2.0 * g * (1.0 + m.poisson) / (3.0 * (1.0 - 2.0 * m.poisson)), g};
  }
  static void update_solid(const Parameters& m, const SolidPoints& p) {
    mooney_rivlin_cauchy(m, p.n, p.f, p.sigma);
  }
};

}  // namespace plyform::material
