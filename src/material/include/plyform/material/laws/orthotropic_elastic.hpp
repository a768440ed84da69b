#pragma once
// *MAT_ORTHOTROPIC_ELASTIC (002), shells: plane stress in the material axes a, b given by AOPT
// (0: the element's edge 1-2, 2: the global vector a, projected on the shell).

#include <algorithm>

#include "plyform/material/laws/law_traits.hpp"

namespace plyform::material {

struct OrthotropicElasticLaw {
  using Parameters = core::OrthotropicElasticMaterial;
  static constexpr LawInfo info{"*MAT_ORTHOTROPIC_ELASTIC", 2, "orthotropic elastic (shells)"};
  static constexpr bool for_solids = false, for_shells = true;
  static constexpr bool needs_deformation_gradient = false, needs_material_axes = true;
  static constexpr std::array<std::string_view, 0> history{};
  static constexpr std::array<std::string_view, 1> results{"stress"};
  /// The stiffest direction bounds the wave speed (time step); the largest shear modulus
  /// scales the hourglass control.
  static const auto& cards(const model::ModelDesc& d) { return d.orthotropic_elastic_materials; }
  static Parameters from_card(const model::MatOrthotropicElasticDesc& c, const DeckCurve&) {
    Parameters law;
    law.density = c.density;
    law.ea = c.ea, law.eb = c.eb, law.ec = c.ec;
    law.prba = c.prba, law.prca = c.prca, law.prcb = c.prcb;
    law.gab = c.gab, law.gbc = c.gbc, law.gca = c.gca;
    law.aopt = c.aopt;
    for (std::size_t k = 0; k < 3; ++k) {
      law.a[k] = c.a[k];
      law.d[k] = c.d[k];
    }
    return law;
  }
  static Moduli moduli(const Parameters& m) {
    const double e = std::max(m.ea, std::max(m.eb, m.ec));
    const double g = std::max(m.gab, std::max(m.gbc, m.gca));
    const double nu = std::max(m.prba, std::max(m.prca, m.prcb));
    return {e / (3.0 * (1.0 - 2.0 * std::min(nu, 0.45))), g};
  }
  static MaterialAxes axes(const Parameters& m) { return {m.aopt, m.a}; }
  static void update_shell(const Parameters& m, std::size_t n, const ShellPoints& p) {
    shell_update(m, n, p, p.cos_t, p.sin_t);
  }
};

}  // namespace plyform::material
