#pragma once
// *MAT_PLASTIC_KINEMATIC (003): J2 plasticity, bilinear hardening mixed between kinematic and
// isotropic by BETA, Cowper-Symonds scaling of the yield stress; radial return about the back
// stress (solids), the exact plane-stress return about it (shells). The back stress is the
// law's history.

#include "plyform/material/laws/law_traits.hpp"
#include "plyform/material/metal_plasticity.hpp"

namespace plyform::material {

struct PlasticKinematicLaw {
  using Parameters = core::PlasticKinematic;
  static constexpr LawInfo info{"*MAT_PLASTIC_KINEMATIC", 3,
                                "J2 plasticity, bilinear kinematic/isotropic hardening, "
                                "Cowper-Symonds rate scaling"};
  static constexpr bool for_solids = true, for_shells = true;
  static constexpr bool needs_deformation_gradient = false, needs_material_axes = false;
  /// The back stress turns with the stresses the shell element turns (its in-plane spin).
  static constexpr bool needs_spin = true;
  /// Solids: the deviatoric back stress; shells: its plane-stress shift (a_xx - a_zz,
  /// a_yy - a_zz, a_xy) in the slots xx, yy, xy, in the co-rotational frame
  /// (docs/materials.md).
  static constexpr std::array<std::string_view, 6> history{"back_stress_xx", "back_stress_yy",
                                                           "back_stress_zz", "back_stress_xy",
                                                           "back_stress_yz", "back_stress_zx"};
  static constexpr std::array<std::string_view, 2> results{"stress", "plastic_strain"};
  static const auto& cards(const model::ModelDesc& d) { return d.plastic_kinematic_materials; }
  static Parameters from_card(const model::MatPlasticKinematicDesc& c, const DeckCurve&) {
    Parameters law;
    law.density = c.density;
    law.young = c.young;
    law.poisson = c.poisson;
    law.sigy = c.sigy;
    law.etan = c.etan;
    law.beta = c.beta;
    law.src = c.src;
    law.srp = c.srp;
    return law;
  }
  static Moduli moduli(const Parameters& m) { return isotropic_moduli(m.young, m.poisson); }
  static void update_solid(const Parameters& m, const SolidPoints& p) {
    solid_update(m, p.n, p.d, p.w[0], p.w[1], p.w[2], p.dt, p.sigma, p.eps_p, p.history);
  }
  static void update_shell(const Parameters& m, std::size_t n, const ShellPoints& p) {
    shell_update(m, n, p, p.dt);
  }
};

}  // namespace plyform::material
