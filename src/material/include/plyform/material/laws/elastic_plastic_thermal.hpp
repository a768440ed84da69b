#pragma once
// *MAT_ELASTIC_PLASTIC_THERMAL (004): J2 plasticity, bilinear isotropic hardening, every constant
// tabulated against temperature; the table's ALPHA is the block's thermal expansion.

#include <algorithm>

#include "plyform/material/laws/law_traits.hpp"
#include "plyform/material/thermal_plasticity.hpp"

namespace plyform::material {

struct ElasticPlasticThermalLaw {
  using Parameters = core::ElasticPlasticThermal;
  static constexpr LawInfo info{"*MAT_ELASTIC_PLASTIC_THERMAL", 4,
                                "J2 plasticity, bilinear hardening, constants against temperature"};
  static constexpr bool for_solids = true, for_shells = true;
  static constexpr bool needs_deformation_gradient = false, needs_material_axes = false;
  static constexpr bool needs_temperature = true;
  static constexpr std::array<std::string_view, 0> history{};
  static constexpr std::array<std::string_view, 2> results{"stress", "plastic_strain"};
  static const auto& cards(const model::ModelDesc& d) {
    return d.elastic_plastic_thermal_materials;
  }
  static Parameters from_card(const model::MatElasticPlasticThermalDesc& c, const DeckCurve&) {
    Parameters law;
    law.density = c.density;
    law.temperature = c.temperature;
    law.young = c.young;
    law.poisson = c.poisson;
    law.alpha = c.alpha;
    law.sigy = c.sigy;
    law.etan = c.etan;
    return law;
  }
  /// The stiffest point of the table (the stable step must hold at every temperature).
  static Moduli moduli(const Parameters& m) {
    Moduli most;
    for (std::size_t i = 0; i < m.young.size(); ++i) {
      const Moduli k = isotropic_moduli(m.young[i], m.poisson[i]);
      most.bulk = std::max(most.bulk, k.bulk);
      most.shear = std::max(most.shear, k.shear);
    }
    return most;
  }
  static void update_solid(const Parameters& m, const SolidPoints& p) {
    solid_update(m, p.n, p.d, p.w[0], p.w[1], p.w[2], p.dt, p.temperature, p.sigma, p.eps_p);
  }
  static void update_shell(const Parameters& m, std::size_t n, const ShellPoints& p) {
    shell_update(m, n, p);
  }
};

}  // namespace plyform::material
