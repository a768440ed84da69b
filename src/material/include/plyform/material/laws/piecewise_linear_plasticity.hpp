#pragma once
// *MAT_PIECEWISE_LINEAR_PLASTICITY (024): J2 plasticity with isotropic hardening from a curve or
// bilinear (SIGY, ETAN); radial return (solids), exact plane-stress return (shells).

#include "plyform/material/laws/law_traits.hpp"
#include "plyform/material/plasticity.hpp"

namespace plyform::material {

struct PiecewiseLinearPlasticityLaw {
  using Parameters = core::PiecewiseLinearPlasticity;
  static constexpr LawInfo info{"*MAT_PIECEWISE_LINEAR_PLASTICITY", 24,
                                "J2 plasticity, isotropic hardening by a curve"};
  static constexpr bool for_solids = true, for_shells = true;
  static constexpr bool needs_deformation_gradient = false, needs_material_axes = false;
  static constexpr std::array<std::string_view, 0> history{};
  static constexpr std::array<std::string_view, 2> results{"stress", "plastic_strain"};
  static const auto& cards(const model::ModelDesc& d) { return d.piecewise_linear_materials; }
  /// LCSS (yield stress against effective plastic strain, or a table of such curves by
  /// strain rate) wins over the 8-point table.
  static Parameters from_card(const model::MatPiecewiseLinearPlasticityDesc& c,
                              const DeckCurve& curve, const DeckTable& table) {
    Parameters law;
    law.density = c.density;
    law.young = c.youngs_modulus;
    law.poisson = c.poisson_ratio;
    law.sigy = c.yield_stress;
    law.etan = c.tangent_modulus;
    law.rate_c = c.c;
    law.rate_p = c.p;
    if (const core::CurveTable* t = c.lcss != 0 ? table(c.lcss) : nullptr) {
      law.rate_values = t->value;
      law.log_rates = !t->value.empty() && t->value.front() < 0.0;
      for (const core::LoadCurve& lc : t->curve)
        law.rate_curves.push_back({lc.x, lc.y});
      law.curve = law.rate_curves.front();  // the yield curve at rest
    } else if (c.lcss != 0) {
      const core::LoadCurve& lc = curve(c.lcss);
      law.curve.plastic_strain = lc.x;
      law.curve.yield_stress = lc.y;
    } else if (!c.eps.empty()) {
      law.curve.plastic_strain = c.eps;
      law.curve.yield_stress = c.es;
    }
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
