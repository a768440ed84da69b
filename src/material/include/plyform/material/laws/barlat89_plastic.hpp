#pragma once
// *MAT_3-PARAMETER_BARLAT (036), shells: the Barlat-Lian 1989 yield function in the material
// axes, hardening by HR, Cowper-Symonds rate scaling.

#include "plyform/material/laws/law_traits.hpp"
#include "plyform/material/laws/sheet_metal_cards.hpp"
#include "plyform/material/sheet_metal_plasticity.hpp"

namespace plyform::material {

struct Barlat89PlasticLaw {
  using Parameters = core::Barlat89Plastic;
  static constexpr LawInfo info{"*MAT_3-PARAMETER_BARLAT", 36,
                                "Barlat-Lian 1989 orthotropic plasticity, shells"};
  static constexpr bool for_solids = false, for_shells = true;
  static constexpr bool needs_deformation_gradient = false, needs_material_axes = true;
  static constexpr std::array<std::string_view, 0> history{};
  static constexpr std::array<std::string_view, 2> results{"stress", "plastic_strain"};
  static const auto& cards(const model::ModelDesc& d) { return d.barlat89_materials; }
  /// R00, R45, R90 give a, c, h, p (barlat89_coefficients); with PB > 0 the card gives them.
  static Parameters from_card(const model::MatBarlat89Desc& c, const DeckCurve& curve) {
    Parameters law;
    law.density = c.density;
    law.young = c.young;
    law.poisson = c.poisson;
    law.hardening = sheet_hardening(c.hardening, c.young, curve);
    law.m = c.m;
    if (c.pb > 0.0) {
      law.a = c.r00, law.c = c.r45, law.h = c.r90, law.p = c.pb;
    } else {
      const Barlat89Coefficients k = barlat89_coefficients(c.r00, c.r45, c.r90, c.m);
      law.a = k.a, law.c = k.c, law.h = k.h, law.p = k.p;
    }
    law.rate_c = c.c;
    law.rate_p = c.p;
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
