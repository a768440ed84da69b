#pragma once
// *MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC (037), shells: Hill's 1948 yield function with
// normal anisotropy R, isotropic hardening by ETAN or the curve HLCID; the exact plane-stress
// return.

#include <cmath>

#include "plyform/material/laws/law_traits.hpp"
#include "plyform/material/metal_plasticity.hpp"

namespace plyform::material {

struct TransverselyAnisotropicPlasticLaw {
  using Parameters = core::TransverselyAnisotropicPlastic;
  static constexpr LawInfo info{"*MAT_TRANSVERSELY_ANISOTROPIC_ELASTIC_PLASTIC", 37,
                                "Hill 1948 plasticity with normal anisotropy R, shells"};
  static constexpr bool for_solids = false, for_shells = true;
  static constexpr bool needs_deformation_gradient = false, needs_material_axes = false;
  static constexpr std::array<std::string_view, 0> history{};
  static constexpr std::array<std::string_view, 2> results{"stress", "plastic_strain"};
  static const auto& cards(const model::ModelDesc& d) {
    return d.transversely_anisotropic_materials;
  }
  /// HLCID (yield stress against effective plastic strain) wins over SIGY and ETAN.
  static Parameters from_card(const model::MatTransverselyAnisotropicDesc& c,
                              const DeckCurve& curve) {
    Parameters law;
    law.density = c.density;
    law.young = c.young;
    law.poisson = c.poisson;
    law.sigy = c.sigy;
    law.etan = c.etan;
    // LS-DYNA: R < 0 asks for its stabilised return with the ratio |R|; plyform's return is
    // exact either way.
    law.r = std::abs(c.r);
    if (c.hlcid != 0) {
      const core::LoadCurve& lc = curve(c.hlcid);
      law.curve.plastic_strain = lc.x;
      law.curve.yield_stress = lc.y;
    }
    return law;
  }
  static Moduli moduli(const Parameters& m) { return isotropic_moduli(m.young, m.poisson); }
  static void update_shell(const Parameters& m, std::size_t n, const ShellPoints& p) {
    shell_update(m, n, p);
  }
};

}  // namespace plyform::material
