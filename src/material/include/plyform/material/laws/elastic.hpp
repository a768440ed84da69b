#pragma once
// *MAT_ELASTIC (001): isotropic, hypoelastic with the Jaumann rate (solids), plane stress
// (shells). Derivation: docs/materials.md.

#include "plyform/material/laws/law_traits.hpp"

namespace plyform::material {

struct ElasticLaw {
  using Parameters = core::ElasticMaterial;
  static constexpr LawInfo info{"*MAT_ELASTIC", 1, "isotropic elastic (Jaumann rate)"};
  static constexpr bool for_solids = true, for_shells = true;
  static constexpr bool needs_deformation_gradient = false, needs_material_axes = false;
  static constexpr std::array<std::string_view, 0> history{};
  static constexpr std::array<std::string_view, 1> results{"stress"};
  static const auto& cards(const model::ModelDesc& d) { return d.elastic_materials; }
  static Parameters from_card(const model::MatElasticDesc& c, const DeckCurve&) {
    return {c.density, c.youngs_modulus, c.poisson_ratio};
  }
  static Moduli moduli(const Parameters& m) { return isotropic_moduli(m.young, m.poisson); }
  static void update_solid(const Parameters& m, const SolidPoints& p) {
    elastic_jaumann(m, p.n, p.d, p.w[0], p.w[1], p.w[2], p.dt, p.sigma);
  }
  static void update_shell(const Parameters& m, std::size_t n, const ShellPoints& p) {
    shell_update(m, n, p);
  }
};

}  // namespace plyform::material
