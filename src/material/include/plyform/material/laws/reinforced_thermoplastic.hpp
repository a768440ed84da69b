#pragma once
// *MAT_REINFORCED_THERMOPLASTIC (249), shells: fibre families in a thermoplastic matrix whose
// directions are per-point history that follow the deformation (woven_ply.hpp).

#include <algorithm>
#include <cmath>
#include <numbers>

#include "plyform/material/laws/law_traits.hpp"
#include "plyform/material/woven_ply.hpp"

namespace plyform::material {

struct ReinforcedThermoplasticLaw {
  using Parameters = core::ReinforcedThermoplastic;
  static constexpr LawInfo info{"*MAT_REINFORCED_THERMOPLASTIC", 249,
                                "fibre families in a thermoplastic matrix (woven ply, shells)"};
  static constexpr bool for_solids = false, for_shells = true;
  static constexpr bool needs_deformation_gradient = false, needs_material_axes = true;
  static constexpr bool needs_temperature = true, needs_frame_turn = true;
  static constexpr std::array<std::string_view, WovenPlyHistory::count> history{
      "fibre1_x",        "fibre1_y",        "fibre2_x",          "fibre2_y",         "fibre3_x",
      "fibre3_y",        "matrix_sxx",      "matrix_syy",        "matrix_sxy",       "jacobian",
      "shear12_plastic", "shear23_plastic", "shear12_hardening", "shear23_hardening"};
  static constexpr std::array<std::string_view, 4> results{"stress", "plastic_strain", "fibre",
                                                           "shear_angle"};
  static const auto& cards(const model::ModelDesc& d) {
    return d.reinforced_thermoplastic_materials;
  }

  /// A curve or table id of the card as a CurveTable (a curve: one value).
  static core::CurveTable curve_or_table(int id, const DeckCurve& curve, const DeckTable& table) {
    if (id == 0)
      return {};
    if (const core::CurveTable* t = table(id))
      return *t;
    return core::CurveTable{{0.0}, {curve(id)}};
  }

  static Parameters from_card(const model::MatReinforcedThermoplasticDesc& c,
                              const DeckCurve& curve, const DeckTable& table) {
    constexpr double deg = std::numbers::pi / 180.0;
    Parameters law;
    law.density = c.density;
    law.young = c.em;
    if (c.lcem != 0)
      law.young_of_t = curve(c.lcem);
    law.poisson = c.prm;
    if (c.lcprm != 0)
      law.poisson_of_t = curve(c.lcprm);
    law.yield = curve_or_table(c.lcsigy, curve, table);
    law.families = c.nfib;
    for (std::size_t i = 0; i < c.fibres.size() && i < 3; ++i) {
      const model::FibreFamilyDesc& f = c.fibres[i];
      auto& p = law.fibre[i];
      p.alpha = f.alpha * deg;
      p.modulus = f.ef;
      p.stress = curve_or_table(f.lcef, curve, table);
      p.g23 = f.g23;
      p.g31 = f.g31;
    }
    for (std::size_t i = 0; i < c.shears.size() && i < 2; ++i) {
      const model::FibreShearDesc& s = c.shears[i];
      auto& p = law.shear[i];
      p.modulus = s.g;
      p.stress = curve_or_table(s.lcg, curve, table);
      p.meth = s.meth;
      // METH 2 curves carry the locking (LS-DYNA ignores ALOC and GLOC there).
      if (p.stress.curve.empty() || s.meth == 3) {
        p.lock_angle = s.aloc;
        p.lock_modulus = s.gloc;
      }
    }
    law.aopt = c.aopt;
    for (std::size_t k = 0; k < 3; ++k) {
      law.a[k] = c.a[k];
      law.v[k] = c.v[k];
    }
    law.angle = c.mangl * deg;
    return law;
  }

  /// The stable step and the hourglass scaling: the stiffest matrix (over its temperature curve)
  /// plus every family's stiffest fibre slope plus four times the stiffest shear slope (a bound
  /// on the in-plane stiffness that the shear between two families adds), with the matrix's
  /// Poisson's ratio.
  static Moduli moduli(const Parameters& m) {
    const auto max_slope = [](const core::CurveTable& t) {
      double s = 0.0;
      for (const core::LoadCurve& c : t.curve) {
        for (std::size_t i = 1; i < c.x.size(); ++i)
          s = std::max(s, std::abs((c.y[i] - c.y[i - 1]) / (c.x[i] - c.x[i - 1])));
      }
      return s;
    };
    double em = m.young;
    for (double y : m.young_of_t.y)
      em = std::max(em, y);
    double e = em;
    for (int i = 0; i < m.families; ++i) {
      const auto& f = m.fibre[static_cast<std::size_t>(i)];
      e += f.stress.curve.empty() ? f.modulus : max_slope(f.stress);
    }
    double g = 0.0;
    for (int k = 0; k + 1 < m.families; ++k) {
      const auto& s = m.shear[static_cast<std::size_t>(k)];
      g = std::max({g, s.modulus, s.lock_modulus, max_slope(s.stress)});
    }
    e += 4.0 * g;
    double nu = m.poisson;
    for (double y : m.poisson_of_t.y)
      nu = std::max(nu, y);
    return isotropic_moduli(e, std::min(nu, 0.45));
  }
  static MaterialAxes axes(const Parameters& m) { return {m.aopt, m.a, m.v, m.angle}; }
  static void update_shell(const Parameters& m, std::size_t n, const ShellPoints& p) {
    shell_update(m, n, p);
  }
};

}  // namespace plyform::material
