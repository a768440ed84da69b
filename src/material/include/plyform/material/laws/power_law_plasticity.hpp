#pragma once
// *MAT_POWER_LAW_PLASTICITY (018): J2 plasticity with sigma_y = k (eps_yp + eps_p)^n.

#include "plyform/material/laws/law_traits.hpp"
#include "plyform/material/plasticity.hpp"

namespace plyform::material {

struct PowerLawPlasticityLaw {
  using Parameters = core::PowerLawPlasticity;
  static constexpr LawInfo info{"*MAT_POWER_LAW_PLASTICITY", 18,
                                "J2 plasticity, power-law hardening"};
  static constexpr bool for_solids = true, for_shells = true;
  static constexpr bool needs_deformation_gradient = false, needs_material_axes = false;
  static constexpr std::array<std::string_view, 0> history{};
  static constexpr std::array<std::string_view, 2> results{"stress", "plastic_strain"};
  static const auto& cards(const model::ModelDesc& d) { return d.power_law_materials; }
  static Parameters from_card(const model::MatPowerLawPlasticityDesc& c, const DeckCurve&) {
    Parameters law;
    law.density = c.density;
    law.young = c.youngs_modulus;
    law.poisson = c.poisson_ratio;
    law.k = c.k;
    law.n = c.n;
    law.sigy = c.sigy;
    law.rate_c = c.src;
    law.rate_p = c.srp;
    return law;
  }
  static Moduli moduli(const Parameters& m) { return isotropic_moduli(m.young, m.poisson); }
  static void update_solid(const Parameters& m, const SolidPoints& p) {
    solid_update(m, p.n, p.d, p.w[0], p.w[1], p.w[2], p.dt, p.sigma, p.eps_p);
  }
  static void update_shell(const Parameters& m, std::size_t n, const ShellPoints& p) {
    shell_update(m, n, p);
  }
};

}  // namespace plyform::material
