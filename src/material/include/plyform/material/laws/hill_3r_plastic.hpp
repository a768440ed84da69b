#pragma once
// *MAT_HILL_3R (122), shells: Hill's 1948 yield function from three Lankford ratios in the
// material axes, hardening by HR.

#include "plyform/material/laws/law_traits.hpp"
#include "plyform/material/laws/sheet_metal_cards.hpp"
#include "plyform/material/sheet_metal_plasticity.hpp"

namespace plyform::material {

struct Hill3RPlasticLaw {
  using Parameters = core::Hill3RPlastic;
  static constexpr LawInfo info{"*MAT_HILL_3R", 122,
                                "Hill 1948 plasticity with R00, R45, R90, shells"};
  static constexpr bool for_solids = false, for_shells = true;
  static constexpr bool needs_deformation_gradient = false, needs_material_axes = true;
  static constexpr std::array<std::string_view, 0> history{};
  static constexpr std::array<std::string_view, 2> results{"stress", "plastic_strain"};
  static const auto& cards(const model::ModelDesc& d) { return d.hill_3r_materials; }
  static Parameters from_card(const model::MatHill3RDesc& c, const DeckCurve& curve) {
    Parameters law;
    law.density = c.density;
    law.young = c.young;
    law.poisson = c.poisson;
    law.hardening = sheet_hardening(c.hardening, c.young, curve);
    law.r00 = c.r00;
    law.r45 = c.r45;
    law.r90 = c.r90;
    law.axes = shell_axes(c.axes);
    return law;
  }
  static Moduli moduli(const Parameters& m) { return isotropic_moduli(m.young, m.poisson); }
  static MaterialAxes axes(const Parameters& m) { return material_axes(m.axes); }
  static void update_shell(const Parameters& m, std::size_t n, const ShellPoints& p) {
    shell_update(m, n, p);
  }
};

}  // namespace plyform::material
